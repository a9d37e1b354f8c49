// spin-orbit: a triaxial body on a fixed Kepler orbit under the quadrupole torque (docs/spin_orbit.md),
// the run of `rotlie spin` as a scene: --h a fraction of the orbital period, --T in orbits.
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/spin_io.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "scene_support.hpp"

namespace rotlie::runs {
namespace {

using namespace scene_support;

scene_result spin_orbit_scene_run(const scene_request& r) {
  for (const char* needed : {"--body", "--e", "--T"})
    if (option(r, needed).empty()) throw bad_input(std::string(needed) + " is required by the spin-orbit scene");
  const auto result = spin_run(spin_setup_of({option(r, "--body"), option(r, "--e"), r.integrator, r.h, option(r, "--T"),
                                              option(r, "--theta0"), option(r, "--omega0"), option(r, "--obliquity"),
                                              option(r, "--scalar"), option(r, "--every")}),
                             [] {  // a caller's stop request (Python's Ctrl-C) ends the run within 64 steps
                               lie::stop_point();
                               return false;
                             });
  auto json = spin_json(result);
  json["scene"] = "spin-orbit";
  return {json, spin_text(result), result.check.warnings};
}

}  // namespace

scene spin_orbit_scene() {
  return {"spin-orbit",
          "a triaxial body on a fixed Kepler orbit under the quadrupole torque (Touma & Wisdom; --h and --T in orbits, as rotlie spin)",
          {{"--body", "", "Hyperion, Moon, Mercury (cited moments), or A,B,C with A <= B <= C"},
           {"--e", "", "Orbital eccentricity in [0, 1)"},
           {"--T", "", "Length of the run in orbits: a whole number of steps --h"},
           {"--theta0", "0", "Initial rotation of the axes A, B, C about z, radians"},
           {"--omega0", "1", "Initial spin about the C axis, units of the mean motion n"},
           {"--obliquity", "0", "Initial tilt of the C axis about x, radians"},
           {"--scalar", "double", "double, long-double or float128"},
           every_option()},
          spin_orbit_scene_run};
}

}  // namespace rotlie::runs
