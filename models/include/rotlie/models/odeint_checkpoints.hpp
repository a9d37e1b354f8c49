#pragma once
// Boost.Odeint's adaptive steppers as rotlie's scenes use them (the spin–orbit scene, the binary scene):
// from checkpoint to checkpoint, the step size carried over, a step shortened only to land on the next
// checkpoint. GCC 12 sees Odeint's coefficient arrays as (maybe) uninitialized when a stepper is copied
// (they are set in its constructor): a false positive inside Boost, silenced here only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
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

}  // namespace rotlie::models

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
