// spin: a triaxial body on a fixed Kepler orbit under the quadrupole torque (the spin–orbit scene),
// any of its integrators, in double, long double or float128: the final attitude and spin.
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "rotlie/runs/spin_io.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::app {

int run_spin(const spin_options& o) {
  const auto setup = runs::spin_setup_of({o.body, o.e, o.integrator, o.h, o.T, o.theta0, o.omega0, o.obliquity, o.scalar, o.every});
  const auto r = runs::spin_run(setup);
  for (const auto& w : r.check.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  if (o.json) {
    std::cout << runs::spin_json(r).dump(2) << "\n";
    return 0;
  }
  const auto I = runs::spin_moments(setup.body);
  std::cout << std::setprecision(10) << "spin-orbit: " << setup.body.name << " (A, B, C = " << I[0] << ", " << I[1] << ", " << I[2]
            << "), e = " << setup.e << ", " << setup.method.name << ", h = " << setup.h << " orbit, " << setup.steps << " steps ("
            << setup.T << " orbits), " << setup.scalar << "\n  Q =";
  for (int i = 0; i < 3; ++i) std::cout << (i ? "\n     " : " ") << r.Q(i, 0) << "  " << r.Q(i, 1) << "  " << r.Q(i, 2);
  std::cout << "\n  omega_body = " << r.omega_body[0] << ", " << r.omega_body[1] << ", " << r.omega_body[2] << " n\n  theta = " << r.theta
            << " rad\n  energy " << r.energy_start << " -> " << r.energy_end << "\n  " << r.check.quantity << " changed by at most "
            << r.check.max_change << " (" << r.check.change_percent << " % of the potential's fluctuation)" << (r.check.unstable ? ": UNSTABLE" : "")
            << "\n  CPU " << r.cpu_s << " s, " << r.evaluations
            << " torque evaluations\n";
  return 0;
}

}  // namespace rotlie::app
