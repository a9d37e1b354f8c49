#pragma once
// The full two-body problem's equations of motion (binary_system::derivative) as 30 unknowns (r, v,
// then each body's Q row-major and G), integrated by an adaptive Runge–Kutta method of Boost.Odeint:
// Runge–Kutta–Fehlberg 7(8) (GUBAS's adaptive method is a 7(8) pair) or Dormand–Prince 5(4), one
// tolerance as both the absolute and the relative one, from checkpoint to checkpoint.
// GCC 12's false warnings inside Odeint: see odeint_warnings_off.hpp.
#include "rotlie/models/odeint_warnings_off.hpp"
#include <array>
#include <limits>
#include <stdexcept>

#include "rotlie/models/scenes/binary_system.hpp"
#include "rotlie/models/odeint_checkpoints.hpp"

namespace rotlie::models {

template <class T>
using binary_ode_state = std::array<T, 30>;

template <class T>
binary_ode_state<T> packed(const binary_state<T>& x) {
  binary_ode_state<T> y{};
  for (std::size_t k = 0; k < 3; ++k) y[k] = x.r[k], y[3 + k] = x.v[k];
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 9; ++k) y[6 + 12 * i + k] = x.body[i].Q.a[k];
    for (std::size_t k = 0; k < 3; ++k) y[15 + 12 * i + k] = x.body[i].G[k];
  }
  return y;
}

template <class T>
binary_state<T> unpacked(const binary_ode_state<T>& y) {
  binary_state<T> x;
  for (std::size_t k = 0; k < 3; ++k) x.r[k] = y[k], x.v[k] = y[3 + k];
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 9; ++k) x.body[i].Q.a[k] = y[6 + 12 * i + k];
    for (std::size_t k = 0; k < 3; ++k) x.body[i].G[k] = y[15 + 12 * i + k];
  }
  return x;
}

template <class T>
class binary_odeint {
 public:
  binary_odeint(binary_system<T> system, odeint_method method, const T& tol, const T& first_dt)
      : system_(std::move(system)), steppers_(method, tol), dt_(first_dt) {}

  const binary_system<T>& system() const { return system_; }
  long evaluations() const { return evaluations_; }
  long steps_tried() const { return tried_; }

  /// Advances x from t to t_next (t is set to t_next).
  void advance(binary_state<T>& x, T& t, const T& t_next) {
    auto y = packed(x);
    const auto rhs = [this](const binary_ode_state<T>& in, binary_ode_state<T>& out, const T& time) {
      out = packed(system_.derivative(unpacked(in), time));
      ++evaluations_;
    };
    steppers_.advance(rhs, y, t, t_next, dt_, [&] { ++tried_; });
    x = unpacked(y);
  }

 private:
  binary_system<T> system_;
  odeint_steppers<binary_ode_state<T>, T> steppers_;
  T dt_;
  long evaluations_ = 0, tried_ = 0;
};

}  // namespace rotlie::models

#include "rotlie/models/odeint_warnings_restore.hpp"
