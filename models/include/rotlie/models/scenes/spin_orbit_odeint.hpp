#pragma once
// The answer a user would otherwise get: the spin–orbit scene's equations of motion,
//   Ġ = G × ω + N(Q, t),   Q̇ = Q ω̂,   ω = I⁻¹ G   (body frame; N from spin_orbit_tide),
// as 12 unknowns (Q row-major, then G) integrated by an adaptive Runge–Kutta method of Boost.Odeint
// (Dormand–Prince 5(4) or Runge–Kutta–Fehlberg 7(8)), error-controlled with one tolerance taken as
// both the absolute and the relative one. Q drifts off the rotations at the size of the tolerance;
// nothing projects it back (the user's plain solution).
// GCC 12's false warnings inside Odeint: see odeint_warnings_off.hpp.
#include "rotlie/models/odeint_warnings_off.hpp"
#include <array>
#include <limits>
#include <stdexcept>
#include <string>

#include "rotlie/models/odeint_checkpoints.hpp"
#include "rotlie/models/scenes/spin_orbit.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::models {

template <class T>
using spin_ode_state = std::array<T, 12>;

template <class T>
struct spin_orbit_ode {
  const spin_orbit_tide<T>* tide;
  long* evaluations;  ///< right-hand sides evaluated (the cost)

  void operator()(const spin_ode_state<T>& x, spin_ode_state<T>& dxdt, const T& t) const {
    body_state<T> s, ds;
    for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] = x[i];
    for (std::size_t i = 0; i < 3; ++i) s.G[i] = x[9 + i];
    euler_rhs(tide->moments(), s, ds);
    const vec3<T> N = tide->body_torque(s.Q, t);
    for (std::size_t i = 0; i < 9; ++i) dxdt[i] = ds.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) dxdt[9 + i] = ds.G[i] + N[i];
    ++*evaluations;
  }
};

/// Adaptive stepping from checkpoint to checkpoint: the step size carries over (and Dormand–Prince's
/// last derivative), a step is only shortened to land on the next checkpoint.
template <class T>
class spin_odeint_stepper {
 public:
  spin_odeint_stepper(const spin_orbit_tide<T>& tide, odeint_method method, const T& tol, const T& first_dt)
      : tide_(tide), steppers_(method, tol), dt_(first_dt) {}

  long evaluations() const { return evaluations_; }

  /// At most `steps` steps (accepted and refused) over the stepper's life; beyond, advance throws.
  void set_step_budget(double steps) { budget_ = steps; }

  /// Advances (s, t) to t_next.
  void advance(body_state<T>& s, T& t, const T& t_next) {
    spin_ode_state<T> x{};
    for (std::size_t i = 0; i < 9; ++i) x[i] = s.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) x[9 + i] = s.G[i];
    const spin_orbit_ode<T> rhs{&tide_, &evaluations_};
    steppers_.advance(rhs, x, t, t_next, dt_, [&] {
      if (++tried_ > budget_)
        throw std::runtime_error("the adaptive run used its budget of " + schemes::message_number(budget_) + " steps by t = " +
                                 schemes::message_number(static_cast<double>(t)) + ": the tolerance asks for more steps than the run can afford (raise it)");
    });
    for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] = x[i];
    for (std::size_t i = 0; i < 3; ++i) s.G[i] = x[9 + i];
  }

 private:
  const spin_orbit_tide<T>& tide_;
  odeint_steppers<spin_ode_state<T>, T> steppers_;
  T dt_;
  double budget_ = std::numeric_limits<double>::infinity();
  double tried_ = 0;
  long evaluations_ = 0;
};

}  // namespace rotlie::models

#include "rotlie/models/odeint_warnings_restore.hpp"
