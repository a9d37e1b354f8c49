#pragma once
// The liquid-water configuration as LAMMPS reads it (atom_style full, units real): one molecule
// per rigid body, atoms O (type 1) and H (type 2) at 3i+1 … 3i+3, site velocities
// v_a = p/m + ω × (Q d_a) with ω = Q I⁻¹ G; and the input lines for the same interaction
// (lj/cut/coul/dsf, intramolecular pairs excluded, LJ shifted) and for fix rigid/nve/small.
// Every number is written with 17 significant digits so that LAMMPS reads the same doubles.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
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

}  // namespace rotlie::models
