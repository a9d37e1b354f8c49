#pragma once
// The liquid-water configuration as LAMMPS reads it (atom_style full, units real): one molecule
// per rigid body, atoms O (type 1) and H (type 2) at 3i+1 … 3i+3, site velocities
// v_a = p/m + ω × (Q d_a) with ω = Q I⁻¹ G; and the input lines for the same interaction
// (lj/cut/coul/dsf, intramolecular pairs excluded, LJ shifted) and for fix rigid/nve/small.
// Every number is written with 17 significant digits so that LAMMPS reads the same doubles.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"

namespace rotlie::models {

inline std::string lammps_number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Writes the data file: box [0, L)³, each molecule's centre wrapped into the box and its sites
/// around it (LAMMPS maps sites outside the box back with image flags).
inline void write_lammps_water_data(const std::filesystem::path& path, const liquid_water<double>& w,
                                    const std::vector<rigid_body_state<double>>& bodies) {
  const auto& m = w.model();
  const double L = w.options().box;
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << "TIP3P water written by rotlie\n\n" << 3 * bodies.size() << " atoms\n2 atom types\n\n";
  out << "0 " << lammps_number(L) << " xlo xhi\n0 " << lammps_number(L) << " ylo yhi\n0 " << lammps_number(L) << " zlo zhi\n\n";
  out << "Masses\n\n1 " << lammps_number(m.mass_O) << "\n2 " << lammps_number(m.mass_H) << "\n\nAtoms # full\n\n";
  std::vector<vec3<double>> velocity(3 * bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto& b = bodies[i];
    vec3<double> centre = b.q;
    for (auto& c : centre) c -= L * std::floor(c / L);
    const vec3<double> omega_body{b.rot.G[0] / m.moments[0], b.rot.G[1] / m.moments[1], b.rot.G[2] / m.moments[2]};
    const vec3<double> omega = b.rot.Q * omega_body;
    for (int a = 0; a < 3; ++a) {
      const vec3<double> r = b.rot.Q * m.site[static_cast<std::size_t>(a)];
      out << 3 * i + static_cast<std::size_t>(a) + 1 << ' ' << i + 1 << ' ' << (a == 0 ? 1 : 2) << ' ' << lammps_number(m.charge[static_cast<std::size_t>(a)]);
      for (int d = 0; d < 3; ++d) out << ' ' << lammps_number(centre[d] + r[d]);
      out << '\n';
      const vec3<double> spin = cross(omega, r);
      for (int d = 0; d < 3; ++d) velocity[3 * i + static_cast<std::size_t>(a)][d] = b.p[d] / m.mass + spin[d];
    }
  }
  out << "\nVelocities\n\n";
  for (std::size_t k = 0; k < velocity.size(); ++k)
    out << k + 1 << ' ' << lammps_number(velocity[k][0]) << ' ' << lammps_number(velocity[k][1]) << ' ' << lammps_number(velocity[k][2]) << '\n';
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

/// The interaction lines: lj/cut/coul/dsf with rotlie's α, cutoff, σ and ε.
inline std::string lammps_water_pair_lines(const liquid_water<double>& w) {
  std::ostringstream s;
  const auto& o = w.options();
  s << "pair_style lj/cut/coul/dsf " << lammps_number(o.dsf_alpha) << ' ' << lammps_number(o.cutoff) << "\n"
    << "pair_coeff 1 1 " << lammps_number(w.model().epsilon) << ' ' << lammps_number(w.model().sigma) << "\n"
    << "pair_coeff 1 2 0.0 1.0\npair_coeff 2 2 0.0 1.0\npair_modify shift yes\n"
    << "neighbor 2.0 bin\nneigh_modify exclude molecule/intra all every 1 delay 0 check yes\n";
  return s.str();
}

/// Reads a LAMMPS `dump custom` file of one frame with columns id and three more; returns them by id.
inline std::map<long, vec3<double>> read_lammps_dump(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::string line;
  std::map<long, vec3<double>> rows;
  bool atoms = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      atoms = true;
      continue;
    }
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = false;
      continue;
    }
    if (!atoms) continue;
    std::istringstream r(line);
    long id;
    vec3<double> v;
    if (r >> id >> v[0] >> v[1] >> v[2]) rows[id] = v;
  }
  return rows;
}

struct lammps_run {
  bool ran = false;
  double wall_ms = 0, cpu_percent = 0, ratio_percent = 0;
};

/// LAMMPS `fix rigid/nve/small` on the configuration with the same pair lines, `steps` steps of h
/// fs on `procs` MPI ranks: per-step wall time from its "Loop time" line, ΔE/ΔV (%) from its thermo
/// output (every step). ran = false when lmp (or mpirun) is missing or fails.
inline lammps_run run_lammps_rigid_nve(const liquid_water<double>& w, const std::vector<rigid_body_state<double>>& bodies, long steps, double h, int procs) {
  lammps_run r;
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) return r;
  if (procs > 1 && std::system("command -v mpirun > /dev/null 2>&1") != 0) return r;
  const auto dir = std::filesystem::temp_directory_path() / ("rotlie_lammps_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_lammps_water_data(dir / "water.data", w, bodies);
  std::ofstream(dir / "in.water") << "units real\natom_style full\nboundary p p p\nread_data water.data\n"
                                  << lammps_water_pair_lines(w) << "fix r all rigid/nve/small molecule\ntimestep " << h
                                  << "\nthermo_style custom step pe etotal\nthermo_modify format float %.15g\nthermo 1\nrun " << steps << "\n";
  const std::string launcher = procs > 1 ? "mpirun --allow-run-as-root -np " + std::to_string(procs) + " " : "";
  const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 " + launcher + "lmp -in in.water -log log.lammps > out.txt 2>&1";
  if (std::system(cmd.c_str()) != 0) {
    std::filesystem::remove_all(dir);  // a failed run leaves no scratch folder behind either
    return r;
  }
  std::ifstream log(dir / "log.lammps");
  std::string line;
  bool thermo = false;
  double es = 0, ess = 0, vs = 0, vss = 0, e0 = 0, v0 = 0;
  long rows = 0;
  const std::regex loop(R"(Loop time of ([0-9.eE+-]+) on)"), cpu(R"(([0-9.]+)% CPU use)");
  std::smatch m;
  while (std::getline(log, line)) {
    if (line.find("Step") != std::string::npos && line.find("PotEng") != std::string::npos) {
      thermo = true;
      continue;
    }
    if (std::regex_search(line, m, loop)) {
      r.wall_ms = 1000 * std::stod(m[1]) / static_cast<double>(steps);
      thermo = false;
    }
    if (std::regex_search(line, m, cpu)) r.cpu_percent = std::stod(m[1]);
    if (thermo) {
      std::istringstream in(line);
      long step;
      double pe, et;
      if (in >> step >> pe >> et) {
        if (step == 0) {
          e0 = et;
          v0 = pe;
          continue;
        }
        es += et - e0;
        ess += (et - e0) * (et - e0);
        vs += pe - v0;
        vss += (pe - v0) * (pe - v0);
        ++rows;
      }
    }
  }
  std::filesystem::remove_all(dir);
  if (rows == 0) return r;
  const double n = static_cast<double>(rows);
  r.ratio_percent = 100 * std::sqrt(ess / n - es * es / (n * n)) / std::sqrt(vss / n - vs * vs / (n * n));
  r.ran = true;
  return r;
}

/// LAMMPS's potential energy and site forces (by atom id − 1) of one configuration (`run 0`);
/// empty forces when lmp is missing or fails.
inline double lammps_single_point(const liquid_water<double>& w, const std::vector<rigid_body_state<double>>& bodies,
                                  std::vector<vec3<double>>& site_force) {
  site_force.clear();
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) return NAN;
  const auto dir = std::filesystem::temp_directory_path() / ("rotlie_lammps_point_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_lammps_water_data(dir / "water.data", w, bodies);
  std::ofstream(dir / "in.water") << "units real\natom_style full\nboundary p p p\nread_data water.data\n" << lammps_water_pair_lines(w)
                                  << "dump f all custom 1 forces.dump id fx fy fz\ndump_modify f format float %.17g sort id\n"
                                     "thermo_style custom step pe\nrun 0\nprint \"pe $(pe:%.17g)\" file result.txt\n";
  const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 lmp -log none -screen none -in in.water > out.txt 2>&1";
  double V = NAN;
  if (std::system(cmd.c_str()) == 0) {
    std::ifstream in(dir / "result.txt");
    std::string key;
    in >> key >> V;
    for (const auto& [id, f] : read_lammps_dump(dir / "forces.dump")) {
      if (site_force.size() < static_cast<std::size_t>(id)) site_force.resize(static_cast<std::size_t>(id));
      site_force[static_cast<std::size_t>(id - 1)] = f;
    }
  }
  std::filesystem::remove_all(dir);
  return V;
}

}  // namespace rotlie::models
