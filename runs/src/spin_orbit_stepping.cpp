// The spin–orbit loop, compiled once per scalar: every study and front end links these three
// instantiations instead of compiling the integrators again (each costs about 10 s of compile time).
#include "rotlie/runs/spin_orbit_stepping.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <type_traits>
#include <vector>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

template <class T>
spin_outcome<T> step_spin_orbit(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h,
                                long steps, const spin_observer<T>& obs) {
  const models::spin_orbit_tide<T> tide(I, e);
  spin_outcome<T> out;
  if (m.adaptive) {
    // Odeint's norms do not take Boost.Multiprecision's float128 (its value_type recursion): the peer
    // runs in double and long double
    if constexpr (!std::is_floating_point_v<T>) {
      throw bad_input("--integrator " + m.name + " runs in double or long double, not in float128");
    } else {
      models::spin_odeint_stepper<T> stepper(tide, m.ode, T(m.tolerance), m.first_step > 0 ? T(m.first_step) : h);
      const double orbits = static_cast<double>(T(steps) * h / boost::math::constants::two_pi<T>());
      stepper.set_step_budget(adaptive_steps_per_orbit * std::max(1.0, orbits));
      out.state = start;
      const double cpu0 = models::thread_cpu_seconds();
      if (obs) {
        for (long k = 1; k <= steps; ++k) {
          stepper.advance(out.state, out.t, T(k) * h);
          obs(k, out.t, out.state);
        }
      } else {
        stepper.advance(out.state, out.t, T(steps) * h);
      }
      out.cpu_s = models::thread_cpu_seconds() - cpu0;
      out.evaluations = stepper.evaluations();
      return out;
    }
  }
  const std::vector<models::body_kind<T>> kinds{{T(1), I, m.rotor ? &*m.rotor : nullptr}};
  models::with_md_integrator<T>(m.splitting, kinds, tide, models::unit_system<T>::natural(), [&](const auto& method) {
    auto x = models::spin_orbit_state(start);
    const double cpu0 = models::thread_cpu_seconds();
    for (long k = 1; k <= steps; ++k) {
      method.step(x, h);  // the engine writes the clock: x.t is k h to round-off (step_clock.hpp)
      if (obs) obs(k, x.t, x.bodies[0].rot);
    }
    out.cpu_s = models::thread_cpu_seconds() - cpu0;
    out.state = x.bodies[0].rot;
    out.t = x.t;
    out.evaluations = x.force_evaluations;
    return 0;
  });
  return out;
}

template spin_outcome<double> step_spin_orbit(const spin_method&, const models::vec3<double>&, const double&, const models::body_state<double>&,
                                              const double&, long, const spin_observer<double>&);
template spin_outcome<long double> step_spin_orbit(const spin_method&, const models::vec3<long double>&, const long double&,
                                                   const models::body_state<long double>&, const long double&, long,
                                                   const spin_observer<long double>&);
template spin_outcome<quad> step_spin_orbit(const spin_method&, const models::vec3<quad>&, const quad&,
                                                     const models::body_state<quad>&, const quad&, long,
                                                     const spin_observer<quad>&);

}  // namespace rotlie::runs
