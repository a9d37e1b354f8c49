// spin: a triaxial body on a fixed Kepler orbit under the quadrupole torque (the spin–orbit scene),
// any of its integrators, in double, long double or float128: the final attitude and spin.
#include <iostream>

#include "commands.hpp"
#include "rotlie/runs/spin_io.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::app {

int run_spin(const spin_options& o) {
  const auto setup = runs::spin_setup_of({o.body, o.e, o.integrator, o.h, o.T, o.theta0, o.omega0, o.obliquity, o.scalar, o.every,
                                            o.accuracy, o.no_error_estimate});
  const auto r = runs::spin_run(setup);
  for (const auto& w : r.check.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  std::cout << (o.json ? runs::spin_json(r).dump(2) + "\n" : runs::spin_text(r));
  return 0;
}

}  // namespace rotlie::app
