// The spin–orbit loop with an observer, compiled once per scalar: a spin_orbit_stepper stepped to the end.
#include "rotlie/runs/spin_orbit_stepping.hpp"

#include <algorithm>
#include <boost/math/constants/constants.hpp>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/spin_orbit_stepper.hpp"

namespace rotlie::runs {

template <class T>
spin_outcome<T> step_spin_orbit(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h,
                                long steps, const spin_observer<T>& obs) {
  spin_orbit_stepper<T> run(m, I, e, start, h);
  if (m.adaptive) {
    const double orbits = static_cast<double>(T(steps) * h / boost::math::constants::two_pi<T>());
    run.set_step_budget(adaptive_steps_per_orbit * std::max(1.0, orbits));
  }
  const double cpu0 = models::thread_cpu_seconds();
  if (obs) {
    for (long k = 1; k <= steps; ++k) {
      run.step();
      obs(k, run.t(), run.state());
    }
  } else {
    run.jump_to(steps);  // an Odeint method straight to the end, choosing its own steps
  }
  spin_outcome<T> out;
  out.cpu_s = models::thread_cpu_seconds() - cpu0;
  out.state = run.state();
  out.t = run.t();
  out.evaluations = run.evaluations();
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
