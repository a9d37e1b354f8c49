#pragma once
// A second, independent solution of Euler's equations with the attitude: classical RK4 on the
// full state, used in tests to validate the exact flow (run it in float128 with a small step).
#include "rotlie/models/rigid_body.hpp"

namespace rotlie::models {

template <class T>
body_state<T> integrate_rk4(const vec3<T>& I, body_state<T> s, const T& t, long steps) {
  const T h = t / static_cast<T>(steps);
  auto axpy = [](const body_state<T>& a, const T& c, const body_state<T>& b) {
    body_state<T> r;
    for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = a.Q.a[i] + c * b.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) r.G[i] = a.G[i] + c * b.G[i];
    return r;
  };
  body_state<T> k1, k2, k3, k4;
  for (long n = 0; n < steps; ++n) {
    euler_rhs(I, s, k1);
    euler_rhs(I, axpy(s, h / 2, k1), k2);
    euler_rhs(I, axpy(s, h / 2, k2), k3);
    euler_rhs(I, axpy(s, h, k3), k4);
    for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] += h / 6 * (k1.Q.a[i] + 2 * k2.Q.a[i] + 2 * k3.Q.a[i] + k4.Q.a[i]);
    for (std::size_t i = 0; i < 3; ++i) s.G[i] += h / 6 * (k1.G[i] + 2 * k2.G[i] + 2 * k3.G[i] + k4.G[i]);
  }
  return s;
}

}  // namespace rotlie::models
