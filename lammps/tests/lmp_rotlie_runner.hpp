// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// Runs lmp_rotlie (on 1 or more MPI ranks) on an input in a scratch folder, and the water start the
// tests share: TIP3P at 0.9973 g/cm³ (cutoff 9 Å) from a lattice, 300 steps at 0.5 fs under a Berendsen
// thermostat in rotlie's own scene (molecules at liquid distances), written as a LAMMPS data file.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/lammps_water_io.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "rotlie/runs/methods.hpp"

namespace rotlie_lammps_test {

namespace fs = std::filesystem;
using namespace rotlie::models;

/// A file's whole text (empty when it is missing).
inline std::string file_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline bool have_mpirun() { return std::string(ROTLIE_MPIEXEC).size() > 0 && fs::exists(ROTLIE_MPIEXEC); }

struct scratch {
  fs::path dir;
  explicit scratch(const std::string& name) : dir(fs::temp_directory_path() / ("rotlie_lmp_" + name + "_" + std::to_string(::getpid()))) {
    fs::create_directories(dir);
  }
  ~scratch() {
    if (std::getenv("ROTLIE_LMP_KEEP")) return;  // to look at a failing run's files
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  /// Runs the input (file `name` in the folder) on `ranks` ranks; the exit status, stdout+stderr in output.
  /// program: lmp_rotlie, or another LAMMPS executable (stock lmp).
  int run(const std::string& name, const std::string& input, int ranks = 1, const std::string& extra = "",
          const std::string& program = ROTLIE_LMP_ROTLIE) {
    std::ofstream(dir / name) << input;
    std::string launcher;
    // Open MPI's flags: root may run it, and more ranks than cores (4 ranks on a 2-core machine)
    if (ranks > 1)
      launcher = std::string(ROTLIE_MPIEXEC) + (::geteuid() == 0 ? " --allow-run-as-root" : "") + (ranks > 2 ? " --oversubscribe" : "") + " -np " +
                 std::to_string(ranks) + " ";
    const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 " + launcher + program + " -in " + name + " -log none " +
                            extra + " > " + name + ".out 2>&1";
    const int status = std::system(cmd.c_str());
    output = file_text(dir / (name + ".out"));
    return status;
  }
  std::string output;
};

struct water_start {
  double L;
  liquid_water<double> w;
  rigid_bodies_state<double> s;
};

/// 9 Å (rotlie's scene uses 11 Å): 216 molecules fit a box larger than twice the cutoff.
inline constexpr double cutoff = 9.0;

inline liquid_water<double> dsf_water(double L) {
  liquid_water_options<double> o;
  o.box = L;
  o.cutoff = cutoff;
  o.interaction = water_interaction::lammps_dsf;
  return liquid_water<double>(tip3p<double>(), o);
}

inline water_start liquid_start(long n) {
  const double L = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  auto s = lattice_water<double>(tip3p<double>(), n, L, 297, 21);
  liquid_water_options<double> o;
  o.box = L;
  o.cutoff = cutoff;
  const liquid_water<double> switched(tip3p<double>(), o);
  with_md_integrator(rotlie::runs::method_named("MRDL", rotlie::runs::method_system::md).splitting, nullptr, tip3p<double>().mass, tip3p<double>().moments, switched, [&](const auto& m) {
    equilibrate(m, s, 0.5, 300, 297.0, 20.0, [](long, double, double) {});
    return 0;
  });
  s.forces_current = false;
  return {L, dsf_water(L), s};
}

inline const std::string water_head = "units real\natom_style full\nboundary p p p\nread_data water.data\n";

/// The largest distance between the sites of two dumps of unwrapped positions (by atom id).
inline double largest_distance(const std::map<long, vec3<double>>& a, const std::map<long, vec3<double>>& b) {
  double worst = a.size() == b.size() ? 0 : INFINITY;
  for (const auto& [id, r] : a) {
    const auto it = b.find(id);
    if (it == b.end()) return INFINITY;
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (r[k] - it->second[k]) * (r[k] - it->second[k]);
    worst = std::max(worst, std::sqrt(d2));
  }
  return worst;
}

/// The final positions and velocities of every atom, to the last digit (restart and loader comparisons).
inline const std::string final_state_dump = "write_dump all custom final.dump id x y z vx vy vz modify format float %.17g sort id\n";
inline const std::string final_dump = "write_dump all custom final.dump id xu yu zu modify format float %.17g sort id\n";

/// `steps` steps of 1 fs of `fix_line` (e.g. "fix r all rigid/sier2/small molecule") in lmp_rotlie on
/// the 216-molecule DSF start, against rotlie's own `integrator` on the same start: the largest site
/// distance (Å), compared modulo the box since LAMMPS's unwrapped positions start from wrapped centres.
/// `output` receives LAMMPS's output when the run fails (the distance is then infinite).
inline double largest_distance_to_rotlie(const std::string& folder, const std::string& fix_line, const char* integrator, int steps,
                                         std::string& output) {
  const auto start = liquid_start(216);
  scratch d(folder);
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string input = water_head + lammps_water_pair_lines(start.w) + fix_line + "\ntimestep 1.0\nthermo 100\nrun " +
                            std::to_string(steps) + "\n" + final_dump;
  if (d.run("in.water", input) != 0) {
    output = d.output;
    return INFINITY;
  }
  const auto rows = read_lammps_dump(d.dir / "final.dump");
  if (rows.size() != 3 * 216u) return INFINITY;
  auto s = start.s;
  with_md_integrator(rotlie::runs::method_named(integrator, rotlie::runs::method_system::md).splitting, nullptr, tip3p<double>().mass, tip3p<double>().moments, start.w, [&](const auto& m) {
    for (int k = 0; k < steps; ++k) m.step(s, 1.0);
    return 0;
  });
  std::vector<vec3<double>> x;
  start.w.site_positions(s.bodies, x);
  double worst = 0;
  for (const auto& [id, r] : rows) {
    const auto& y = x[static_cast<std::size_t>(id - 1)];
    const vec3<double> dx = minimum_image(vec3<double>{r[0] - y[0], r[1] - y[1], r[2] - y[2]}, start.L);
    worst = std::max(worst, std::sqrt(dot(dx, dx)));
  }
  return worst;
}

}  // namespace rotlie_lammps_test
