#pragma once
// Boost.Odeint's adaptive steppers as rotlie's scenes use them (the spin–orbit scene, the binary scene):
// from checkpoint to checkpoint, the step size carried over, a step shortened only to land on the next
// checkpoint. GCC 12's false warnings inside Odeint: see odeint_warnings_off.hpp.
#include "rotlie/models/odeint_warnings_off.hpp"
#include <boost/numeric/odeint.hpp>

#include <stdexcept>

namespace rotlie::models {

enum class odeint_method { dopri5, rkf78 };

/// Advances (x, t) to t_next with `stepper` (a controlled Odeint stepper) on `rhs`, starting from the
/// trial step dt and leaving in dt the step to try next; `before_try()` runs before every try (a step
/// budget throws there). Throws std::runtime_error after 500 refusals in a row.
template <class Controlled, class Rhs, class State, class T, class BeforeTry>
void advance_to_checkpoint(Controlled& stepper, const Rhs& rhs, State& x, T& t, const T& t_next, T& dt, BeforeTry&& before_try) {
  namespace ode = boost::numeric::odeint;
  int refused = 0;
  while (t < t_next) {
    before_try();
    const bool last = dt >= t_next - t;
    T step = last ? t_next - t : dt;
    const T kept = dt;
    if (stepper.try_step(rhs, x, t, step) == ode::success) {
      refused = 0;
      dt = last && step < kept ? kept : step;  // a step cut to land on the checkpoint does not shrink the next
      if (last) t = t_next;
    } else {
      dt = step;
      if (++refused > 500) throw std::runtime_error("the adaptive Runge-Kutta step fell below what the tolerance allows");
    }
  }
}

/// The two adaptive methods on one State, each controlled with `tol` as both the absolute and the
/// relative tolerance; advance() runs the chosen one to a checkpoint (advance_to_checkpoint).
template <class State, class T>
class odeint_steppers {
  using dopri5 = boost::numeric::odeint::runge_kutta_dopri5<State, T>;
  using rkf78 = boost::numeric::odeint::runge_kutta_fehlberg78<State, T>;
  using controlled_dopri5 = typename boost::numeric::odeint::result_of::make_controlled<dopri5>::type;
  using controlled_rkf78 = typename boost::numeric::odeint::result_of::make_controlled<rkf78>::type;

 public:
  odeint_steppers(odeint_method method, const T& tol)
      : method_(method),
        dopri5_(boost::numeric::odeint::make_controlled(tol, tol, dopri5())),
        rkf78_(boost::numeric::odeint::make_controlled(tol, tol, rkf78())) {
    if (!(tol > 0)) throw std::invalid_argument("the tolerance must be positive");
  }

  template <class Rhs, class BeforeTry>
  void advance(const Rhs& rhs, State& x, T& t, const T& t_next, T& dt, BeforeTry&& before_try) {
    if (method_ == odeint_method::dopri5)
      advance_to_checkpoint(dopri5_, rhs, x, t, t_next, dt, before_try);
    else
      advance_to_checkpoint(rkf78_, rhs, x, t, t_next, dt, before_try);
  }

 private:
  odeint_method method_;
  controlled_dopri5 dopri5_;
  controlled_rkf78 rkf78_;
};

}  // namespace rotlie::models

#include "rotlie/models/odeint_warnings_restore.hpp"
