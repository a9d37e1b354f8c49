#pragma once
// The spin–orbit scene stepped in any scalar with any of its integrators, an observer called after
// each step: the one loop behind spin_run, the tests and bench/spin_bench.
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

template <class T>
struct spin_outcome {
  models::body_state<T> state;
  T t{};
  double cpu_s = 0;       ///< CPU seconds of the stepping (observer included)
  long evaluations = 0;  ///< torque evaluations
};

/// The body's moments in T, each read once from its exact text.
template <class T>
models::vec3<T> spin_moments_in(const spin_body& body) {
  std::string text = body.moments;
  std::replace(text.begin(), text.end(), ',', ' ');
  return models::moments_from_text<T>(text);
}

namespace detail {
struct no_spin_observer {
  template <class T>
  void operator()(long, const T&, const models::body_state<T>&) const {}
};
}  // namespace detail

/// `steps` steps of length h (time units: the orbital period is 2π) from `start` at t = 0, calling
/// obs(k, t, state) after step k. An Odeint method takes h (or m.first_step) as its first trial step and chooses its
/// own steps; with an observer it lands on every k h, without one it runs straight to steps·h.
template <class T, class Observer>
spin_outcome<T> step_spin_orbit(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h,
                                long steps, Observer&& obs) {
  constexpr bool observed = !std::is_same_v<std::decay_t<Observer>, detail::no_spin_observer>;
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
    if constexpr (observed) {
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
      obs(k, x.t, x.bodies[0].rot);
    }
    out.cpu_s = models::thread_cpu_seconds() - cpu0;
    out.state = x.bodies[0].rot;
    out.t = x.t;
    out.evaluations = x.force_evaluations;
    return 0;
  });
  return out;
}

/// The same without an observer.
template <class T>
spin_outcome<T> step_spin_orbit(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h,
                                long steps) {
  return step_spin_orbit(m, I, e, start, h, steps, detail::no_spin_observer{});
}

}  // namespace rotlie::runs
