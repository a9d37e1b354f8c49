#pragma once
// The exact Kepler flow of a relative orbit, r̈ = −GM r/|r|³, for any time step and any orbit
// (elliptic, parabolic, hyperbolic), in universal variables (Danby 1988, §6.9; Battin 1999, §4.5):
// the universal anomaly χ solves
//   √GM Δt = r₀ v_r0/√GM χ² C(αχ²) + (1 − αr₀) χ³ S(αχ²) + r₀ χ,   α = 2/r₀ − v₀²/GM,
// by Newton's method, with Stumpff's C(z) = (1 − cos √z)/z and S(z) = (√z − sin √z)/√z³ (series
// near z = 0); then r = f r₀ + g v₀, v = ḟ r₀ + ġ v₀ with Lagrange's f, g. The flow keeps r × v
// (f ġ − ḟ g = 1) and is the drift of a Wisdom–Holman split.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

namespace kepler_detail {

/// C(z) and S(z); the series where |z| is small keeps full precision in any scalar.
template <class T>
void stumpff(const T& z, T& C, T& S) {
  using std::abs;
  using std::cos;
  using std::cosh;
  using std::sin;
  using std::sinh;
  using std::sqrt;
  if (abs(z) < T(0.5)) {
    // C = Σ (−z)^k / (2k+2)!, S = Σ (−z)^k / (2k+3)!
    T term_c = T(1) / 2, term_s = T(1) / 6;
    C = 0, S = 0;
    for (int k = 0; k < 40; ++k) {
      C += term_c, S += term_s;
      term_c *= -z / T((2 * k + 3) * (2 * k + 4));
      term_s *= -z / T((2 * k + 4) * (2 * k + 5));
      if (abs(term_c) <= std::numeric_limits<T>::epsilon() * abs(C) / 4 && abs(term_s) <= std::numeric_limits<T>::epsilon() * abs(S) / 4) break;
    }
  } else if (z > 0) {
    const T s = sqrt(z);
    C = (1 - cos(s)) / z;
    S = (s - sin(s)) / (s * z);
  } else {
    const T s = sqrt(-z);
    C = (cosh(s) - 1) / -z;
    S = (sinh(s) - s) / (s * -z);
  }
}

}  // namespace kepler_detail

/// Advances (r, v) along the Kepler orbit of gravitational parameter GM by dt (any sign).
template <class T>
void kepler_drift(vec3<T>& r, vec3<T>& v, const T& GM, const T& dt) {
  using std::abs;
  using std::sqrt;
  using kepler_detail::stumpff;
  const T r0 = sqrt(dot(r, r)), rv = dot(r, v), v2 = dot(v, v), sqrt_mu = sqrt(GM);
  const T alpha = 2 / r0 - v2 / GM;  // 1/a
  T time = dt;
  if (alpha > 0) {  // an ellipse: whole periods change nothing
    const T period = 2 * std::acos(T(-1)) / (alpha * sqrt(alpha) * sqrt_mu);
    using std::round;
    time -= period * round(dt / period);
  }
  const T sigma = rv / sqrt_mu;  // r₀ v_r0 / √GM
  // first guess: the mean motion's angle for an ellipse, else the straight line
  T chi = alpha > 0 ? sqrt_mu * time * alpha : sqrt_mu * time / r0;
  T C = 0, S = 0, r_new = r0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const T z = alpha * chi * chi;
    stumpff(z, C, S);
    const T chi2 = chi * chi;
    const T F = sigma * chi2 * C + (1 - alpha * r0) * chi2 * chi * S + r0 * chi - sqrt_mu * time;
    r_new = sigma * chi * (1 - z * S) + (1 - alpha * r0) * chi2 * C + r0;  // dF/dχ = |r|
    const T delta = F / r_new;
    chi -= delta;
    if (abs(delta) <= 4 * std::numeric_limits<T>::epsilon() * abs(chi) || delta == T(0)) break;
    if (iteration == 99) throw std::runtime_error("Kepler drift: the universal anomaly did not converge");
  }
  const T z = alpha * chi * chi;
  stumpff(z, C, S);
  const T chi2 = chi * chi;
  const T f = 1 - chi2 / r0 * C, g = time - chi2 * chi / sqrt_mu * S;
  vec3<T> r1;
  for (std::size_t k = 0; k < 3; ++k) r1[k] = f * r[k] + g * v[k];
  const T r1n = sqrt(dot(r1, r1));
  const T fdot = sqrt_mu / (r1n * r0) * (z * chi * S - chi), gdot = 1 - chi2 / r1n * C;
  for (std::size_t k = 0; k < 3; ++k) v[k] = fdot * r[k] + gdot * v[k];
  r = r1;
}

}  // namespace rotlie::models
