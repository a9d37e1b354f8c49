#pragma once
// The answer a user would otherwise get: the spin–orbit scene's equations of motion,
//   Ġ = G × ω + N(Q, t),   Q̇ = Q ω̂,   ω = I⁻¹ G   (body frame; N from spin_orbit_tide),
// as 12 unknowns (Q row-major, then G) integrated by an adaptive Runge–Kutta method of Boost.Odeint
// (Dormand–Prince 5(4) or Runge–Kutta–Fehlberg 7(8)), error-controlled with one tolerance taken as
// both the absolute and the relative one. Q drifts off the rotations at the size of the tolerance;
// nothing projects it back (the user's plain solution).
// GCC 12 sees Odeint's coefficient arrays as (maybe) uninitialized when a stepper is copied (they are set
// in its constructor): a false positive inside Boost, silenced here only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
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
  using dopri5 = boost::numeric::odeint::runge_kutta_dopri5<spin_ode_state<T>, T>;
  using rkf78 = boost::numeric::odeint::runge_kutta_fehlberg78<spin_ode_state<T>, T>;
  using controlled_dopri5 = typename boost::numeric::odeint::result_of::make_controlled<dopri5>::type;
  using controlled_rkf78 = typename boost::numeric::odeint::result_of::make_controlled<rkf78>::type;

 public:
  spin_odeint_stepper(const spin_orbit_tide<T>& tide, odeint_method method, const T& tol, const T& first_dt)
      : tide_(tide),
        method_(method),
        dt_(first_dt),
        dopri5_(boost::numeric::odeint::make_controlled(tol, tol, dopri5())),
        rkf78_(boost::numeric::odeint::make_controlled(tol, tol, rkf78())) {
    if (!(tol > 0)) throw std::invalid_argument("the tolerance must be positive");
  }

  long evaluations() const { return evaluations_; }

  /// At most `steps` steps (accepted and refused) over the stepper's life; beyond, advance throws.
  void set_step_budget(double steps) { budget_ = steps; }

  /// Advances (s, t) to t_next.
  void advance(body_state<T>& s, T& t, const T& t_next) {
    spin_ode_state<T> x{};
    for (std::size_t i = 0; i < 9; ++i) x[i] = s.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) x[9 + i] = s.G[i];
    if (method_ == odeint_method::dopri5)
      run(dopri5_, x, t, t_next);
    else
      run(rkf78_, x, t, t_next);
    for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] = x[i];
    for (std::size_t i = 0; i < 3; ++i) s.G[i] = x[9 + i];
  }

 private:
  template <class Controlled>
  void run(Controlled& stepper, spin_ode_state<T>& x, T& t, const T& t_next) {
    const spin_orbit_ode<T> rhs{&tide_, &evaluations_};
    advance_to_checkpoint(stepper, rhs, x, t, t_next, dt_, [&] {
      if (++tried_ > budget_)
        throw std::runtime_error("the adaptive run used its budget of " + schemes::message_number(budget_) + " steps by t = " +
                                 schemes::message_number(static_cast<double>(t)) + ": the tolerance asks for more steps than the run can afford (raise it)");
    });
  }

  const spin_orbit_tide<T>& tide_;
  double budget_ = std::numeric_limits<double>::infinity();
  double tried_ = 0;
  odeint_method method_;
  T dt_;
  controlled_dopri5 dopri5_;
  controlled_rkf78 rkf78_;
  long evaluations_ = 0;
};

}  // namespace rotlie::models

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
