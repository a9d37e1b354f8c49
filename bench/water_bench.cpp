// Liquid-water cost per step (not a test): TIP3P at 0.9973 g/cm³ with the 11 Å smooth molecular
// cutoff, 512, 4096 and 32768 molecules, one and two threads, SIER2 and MRDL; then the same
// 512-molecule configuration with lj/cut/coul/dsf in rotlie (Strang-TV + ABCBA2:ABC, the map of
// LAMMPS's NO_SQUISH) and in LAMMPS `fix rigid/nve/small` (skipped where `lmp` is missing), with
// the energy fluctuation of both runs. Wall and CPU time are both printed: on a shared machine
// wall time overstates the cost.
//   water_bench [--quick | --lammps]   (--quick: up to 4096 molecules, 100 steps side by side; --lammps: only that)
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/lammps_water_io.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_setup.hpp"

using namespace rotlie::models;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct cost {
  double wall_ms = 0, cpu_ms = 0;
};

liquid_water<double> scene(long n, int threads, water_interaction kind = water_interaction::switched_molecular) {
  liquid_water_options<double> o;
  o.box = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  o.threads = threads;
  o.interaction = kind;
  return liquid_water<double>(tip3p<double>(), o);
}

// The bench links the numeric core alone: its integrators by their parts (runs/methods.hpp names them).
md_integrator mrdl() { return md_integrator_of("MRDL", "Strang-TV", mrdl_rotor_table); }

/// A liquid-like start: the lattice and `settle` thermostatted steps at 0.5 fs.
rigid_bodies_state<double> start(long n, int settle) {
  auto s = lattice_water<double>(tip3p<double>(), n, cubic_box_side<double>(n, tip3p<double>().mass, 0.9973), 297, 17);
  const auto w = scene(n, 2);
  with_md_integrator(mrdl(), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    equilibrate(m, s, 0.5, settle, 297.0, 20.0, [](long, double, double) {});
    return 0;
  });
  s.forces_current = false;
  return s;
}

cost time_steps(const md_integrator& integrator, const liquid_water<double>& w, rigid_bodies_state<double> s, long steps, double h,
                double* ratio = nullptr) {
  cost c;
  with_md_integrator(integrator, nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    s.forces_current = false;
    m.step(s, h);  // the first list build and force evaluation outside the clock
    const auto& sys = m.system();
    double es = 0, ess = 0, vs = 0, vss = 0;
    const double e0 = sys.energy(s), v0 = sys.potential_energy(s);
    const double cpu0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) {
      m.step(s, h);
      if (ratio) {
        const double V = sys.potential_energy(s), E = V + sys.kinetic_energy(s);
        es += E - e0;
        ess += (E - e0) * (E - e0);
        vs += V - v0;
        vss += (V - v0) * (V - v0);
      }
    }
    c.wall_ms = 1000 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / static_cast<double>(steps);
    c.cpu_ms = 1000 * (cpu_seconds() - cpu0) / static_cast<double>(steps);
    if (ratio) {
      const double n = static_cast<double>(steps);
      *ratio = 100 * std::sqrt(ess / n - es * es / (n * n)) / std::sqrt(vss / n - vs * vs / (n * n));
    }
    return 0;
  });
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  const bool quick = mode == "--quick", lammps_only = mode == "--lammps";
  std::printf("# liquid water, TIP3P, 0.9973 g/cm^3, 11 A molecular switch (9.5-11 A), skin 1 A\n");
  std::printf("%-8s %-6s %-8s %-12s %-12s %-12s\n", "N", "thr", "method", "wall ms/st", "cpu ms/st", "us/mol-step");
  for (long n : {512L, 4096L, 32768L}) {
    if ((quick && n > 4096) || lammps_only) break;
    const auto s = start(n, n <= 512 ? 400 : 100);
    const long steps = n <= 512 ? 200 : n <= 4096 ? 20 : 4;
    for (int threads : {1, 2}) {
      const auto w = scene(n, threads);
      for (const auto& integrator : {mrdl(), md_integrator_of("SIER2", "Strang-TV", "exact")}) {
        const cost c = time_steps(integrator, w, s, steps, 1.0);
        std::printf("%-8ld %-6d %-8s %-12.3f %-12.3f %-12.3f\n", n, threads, integrator.name.c_str(), c.wall_ms, c.cpu_ms, 1000 * c.wall_ms / static_cast<double>(n));
        std::fflush(stdout);
      }
    }
  }
  // side by side with LAMMPS: same configuration, same pair style, same map
  const long n = 512, steps = quick ? 100 : 1000;
  const auto s = start(n, 1000);
  std::printf("\n# 512 molecules, lj/cut/coul/dsf (alpha 0.2, 11 A), h = 1 fs, %ld steps, NO_SQUISH order (Strang-TV + ABCBA2:ABC)\n", steps);
  for (int threads : {1, 2}) {
    double ratio = 0;
    const cost c = time_steps("SIER2/ABCBA2:ABC", scene(n, threads, water_interaction::lammps_dsf), s, steps, 1.0, &ratio);
    std::printf("rotlie  %d thread(s): wall %.3f ms/step, cpu %.3f ms/step, dE/dV %.4f %%\n", threads, c.wall_ms, c.cpu_ms, ratio);
    std::fflush(stdout);
  }
  for (int procs : {1, 2}) {
    const auto r = run_lammps_rigid_nve(scene(n, 1, water_interaction::lammps_dsf), s.bodies, steps, 1.0, procs);
    if (!r.ran)
      std::printf("LAMMPS  %d proc(s): skipped (lmp%s not found or failed)\n", procs, procs > 1 ? " or mpirun" : "");
    else
      std::printf("LAMMPS  %d proc(s): wall %.3f ms/step (%.1f%% CPU use), dE/dV %.4f %%\n", procs, r.wall_ms, r.cpu_percent, r.ratio_percent);
    std::fflush(stdout);
  }
  return 0;
}
