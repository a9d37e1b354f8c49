#pragma once
// Shared pieces of the numeric tests: float128, water and state helpers, and a float128 reference
// solution of Euler's equations (RK4 with Richardson extrapolation: global error O(h^5)).

#include "rotlie/models/reference_integration.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::test {

template <class T>
models::vec3<T> water_moments() {
  return {T(10220) / T(29376), T(19187) / T(29376), T(1)};
}

template <class T>
models::body_state<T> initial_state(const models::vec3<T>& G) {
  models::body_state<T> s;
  s.G = G;
  return s;
}

/// (16 y_{h/2} − y_h)/15 with RK4: the h^4 term cancels.
inline models::body_state<quad> reference_solution(const models::vec3<quad>& I, const models::body_state<quad>& s0,
                                                   const quad& t, long steps) {
  const auto coarse = models::integrate_rk4(I, s0, t, steps), fine = models::integrate_rk4(I, s0, t, 2 * steps);
  models::body_state<quad> r;
  for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = (16 * fine.Q.a[i] - coarse.Q.a[i]) / 15;
  for (std::size_t i = 0; i < 3; ++i) r.G[i] = (16 * fine.G[i] - coarse.G[i]) / 15;
  return r;
}

template <class T, class U>
double attitude_distance(const models::mat3<T>& a, const models::mat3<U>& b) {
  double s = 0;
  for (std::size_t i = 0; i < 9; ++i) {
    const double d = static_cast<double>(a.a[i]) - static_cast<double>(b.a[i]);
    s += d * d;
  }
  return std::sqrt(s);
}

}  // namespace rotlie::test
