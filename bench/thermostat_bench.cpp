// What a thermostat costs on liquid water (not a test): rigid TIP3P at 4,096 molecules (the 11 Å
// smooth molecular cutoff, one thread), CPU ms per step of SIER2 at constant energy, SIER2-BAOAB,
// SIER2-OBABO and SIER2-NHC from the same configuration, and each thermostat's stage alone (the
// O-step over every molecule, the chains' flow): its share of a step, the goal being 5 %.
//   thermostat_bench [MOLECULES [STEPS]]   (default 4096 molecules, 40 steps)
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/real_units.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_setup.hpp"

using namespace rotlie::models;
using rotlie::schemes::thermostat_placement;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// CPU ms per call of f, over n calls.
template <class F>
double cpu_ms(long n, F&& f) {
  const double c0 = cpu_seconds();
  for (long k = 0; k < n; ++k) f();
  return 1000 * (cpu_seconds() - c0) / static_cast<double>(n);
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 4096, steps = argc > 2 ? std::atol(argv[2]) : 40;
  if (n < 365 || steps < 1) {
    std::fprintf(stderr, "usage: thermostat_bench [MOLECULES >= 365 [STEPS >= 1]]\n");
    return 2;
  }
  liquid_water_options<double> o;
  o.box = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  o.threads = 1;
  const liquid_water<double> w(tip3p<double>(), o);
  auto start = lattice_water<double>(tip3p<double>(), n, o.box, 300, 17);
  const std::vector<body_kind<double>> kinds{{tip3p<double>().mass, tip3p<double>().moments}};
  const auto sier2 = md_integrator_of("SIER2", "Strang-TV", "exact");
  with_md_integrator(sier2, kinds, w, unit_system<double>::real(), [&](const auto& m) {
    equilibrate(m, start, 0.25, 200, 300.0, 10.0, [](long, double, double) {});  // off the lattice
    return 0;
  });
  const double h = 2;
  std::printf("liquid water, %ld TIP3P molecules, one thread, h = %g fs, CPU ms (mean of %ld steps)\n", n, h, steps);
  const double nve = with_md_integrator(sier2, kinds, w, unit_system<double>::real(), [&](const auto& m) {
    auto s = start;
    s.forces_current = false;
    m.step(s, h);
    return cpu_ms(steps, [&] { m.step(s, h); });
  });
  std::printf("  %-14s %8.3f ms per step\n", "SIER2 (NVE)", nve);
  thermostat_parameters bath;
  bath.kT = real_units::boltz<double>() * 300, bath.friction = 1e-3, bath.tau = 100;
  for (const auto& [name, placement] : {std::pair{"SIER2-BAOAB", thermostat_placement::middle}, std::pair{"SIER2-OBABO", thermostat_placement::ends},
                                        std::pair{"SIER2-NHC", thermostat_placement::chain}})
    with_thermostatted_integrator(sier2, placement, bath, kinds, w, unit_system<double>::real(), [&](const auto& m) {
      auto s = start;
      s.forces_current = false;
      m.step(s, h);
      const double step = cpu_ms(steps, [&] { m.step(s, h); });
      const auto& sys = m.system();
      const double stage = placement == thermostat_placement::chain ? 2 * cpu_ms(20 * steps, [&] { sys.chains(h / 2, s); })
                                                                    : (placement == thermostat_placement::ends ? 2 : 1) * cpu_ms(20 * steps, [&] {
                                                                        sys.langevin(placement == thermostat_placement::ends ? h / 2 : h, s);
                                                                      });
      std::printf("  %-14s %8.3f ms per step (%.3f× NVE); the thermostat's stages %.4f ms: %.2f %% of the step\n", name, step, step / nve, stage,
                  100 * stage / step);
      return 0;
    });
  return 0;
}
