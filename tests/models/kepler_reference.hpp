#pragma once
// An independent two-body reference in float128: the classical elements of (r₀, v₀) and Kepler's
// equation in the anomaly of each conic (E − e sin E = M, e sinh H − H = M, Barker's D + D³/3 = B),
// solved by bisection to the last bit, then the position and velocity in the perifocal frame. The
// small differences (1 − e, E − sin E, cosh H − 1, …) are formed without cancellation, so that e → 1
// keeps float128's precision.
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>

#include "rotlie/models/small_matrix.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::test {

using models::vec3;

namespace kepler_ref {

inline vec3<quad> cross(const vec3<quad>& a, const vec3<quad>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline quad norm(const vec3<quad>& a) { return sqrt(models::dot(a, a)); }

/// x − sin x and sinh x − x, by their series where they are small.
inline quad x_minus_sin(const quad& x) {
  if (abs(x) > quad(0.5)) return x - sin(x);
  quad term = x * x * x / 6, sum = 0;
  for (int k = 1; k < 60 && term != 0; ++k) sum += term, term *= -x * x / ((2 * k + 2) * (2 * k + 3));
  return sum;
}
inline quad sinh_minus_x(const quad& x) {
  if (abs(x) > quad(0.5)) return sinh(x) - x;
  quad term = x * x * x / 6, sum = 0;
  for (int k = 1; k < 60 && term != 0; ++k) sum += term, term *= x * x / ((2 * k + 2) * (2 * k + 3));
  return sum;
}

/// The root of an increasing g in [lo, hi] (g(lo) ≤ 0 ≤ g(hi)), bisected until the bracket cannot shrink.
template <class G>
quad bisect(const G& g, quad lo, quad hi) {
  for (int k = 0; k < 20000; ++k) {
    const quad mid = (lo > 0 && hi > 4 * lo) ? sqrt(lo * hi) : lo + (hi - lo) / 2;
    if (!(mid > lo && mid < hi)) break;
    (g(mid) < 0 ? lo : hi) = mid;
  }
  return lo + (hi - lo) / 2;
}

}  // namespace kepler_ref

/// The state at time t of the orbit through (r, v) with GM = mu, in float128.
inline void kepler_reference(vec3<quad>& r, vec3<quad>& v, const quad& mu, const quad& t) {
  using namespace kepler_ref;
  const quad pi = boost::math::constants::pi<quad>();
  const quad r0 = norm(r), v2 = models::dot(v, v), rv = models::dot(r, v);
  const vec3<quad> h = cross(r, v);
  const quad hn = norm(h), p = models::dot(h, h) / mu;  // the semi-latus rectum
  // the eccentricity vector and the perifocal frame (P at the pericentre; P = r̂₀ on a circle)
  vec3<quad> e_vec;
  for (int k = 0; k < 3; ++k) e_vec[k] = ((v2 - mu / r0) * r[k] - rv * v[k]) / mu;
  const quad e = norm(e_vec);
  vec3<quad> P, Q, hh;
  for (int k = 0; k < 3; ++k) P[k] = e > 0 ? e_vec[k] / e : r[k] / r0, hh[k] = h[k] / hn;
  Q = cross(hh, P);
  const quad x0 = models::dot(r, P), y0 = models::dot(r, Q);
  const quad alpha = 2 / r0 - v2 / mu;  // 1/a
  // 1 − e without cancellation: (1 − e²) = p α, so 1 − e = p α / (1 + e)
  const quad one_minus_e = p * alpha / (1 + e);
  quad x, y, vx, vy;
  if (alpha > 0) {
    const quad a = 1 / alpha, n = sqrt(mu * alpha * alpha * alpha), b = sqrt(a * p);
    const quad E0 = atan2(y0 / b, x0 / a + e);
    const auto kepler = [&](const quad& E) { return one_minus_e * E + e * x_minus_sin(E); };  // E − e sin E
    quad M = kepler(E0) + n * t;
    const quad turns = round(M / (2 * pi));
    M -= 2 * pi * turns;  // to [−π, π]; E then differs from M by the same turns
    const quad E = bisect([&](const quad& E_) { return kepler(E_) - M; }, -pi, pi);
    const quad s = sin(E / 2), rn = a * one_minus_e + 2 * a * e * s * s;
    x = a * one_minus_e - 2 * a * s * s;  // a (cos E − e)
    y = b * sin(E);
    vx = -sqrt(mu * a) * sin(E) / rn;
    vy = sqrt(mu * p) * cos(E) / rn;
  } else if (alpha < 0) {
    const quad A = -1 / alpha, n = sqrt(mu / (A * A * A)), bb = sqrt(A * p);
    const quad e_minus_1 = -one_minus_e;
    const quad H0 = asinh(y0 / bb);
    const auto kepler = [&](const quad& H) { return e_minus_1 * H + e * sinh_minus_x(H); };  // e sinh H − H
    const quad M = kepler(H0) + n * t;
    // e sinh H − H ≥ (e − 1) sinh H and ≥ e H³/6 for H ≥ 0: the root's bound
    const quad m = abs(M);
    quad bound = cbrt(6 * m / e);
    if (e_minus_1 > 0) bound = std::min(bound, asinh(m / e_minus_1));
    bound = bound * 2 + 1;
    const quad Hm = bisect([&](const quad& H) { return kepler(H) - m; }, quad(0), bound);
    const quad H = M < 0 ? -Hm : Hm;
    const quad s = sinh(H / 2), rn = A * e_minus_1 + 2 * A * e * s * s;
    x = A * e_minus_1 - 2 * A * s * s;  // A (e − cosh H)
    y = bb * sinh(H);
    vx = -sqrt(mu * A) * sinh(H) / rn;
    vy = sqrt(mu * p) * cosh(H) / rn;
  } else {
    // a parabola: t − t_p = √(p³/μ)/2 (D + D³/3), D = tan(f/2), r = p (1 + D²)/2
    const quad D0 = y0 / p;
    const quad B = D0 + D0 * D0 * D0 / 3 + 2 * sqrt(mu / (p * p * p)) * t;
    const quad m = abs(B);
    const quad Dm = bisect([&](const quad& D) { return D + D * D * D / 3 - m; }, quad(0), std::min(m, cbrt(3 * m)) + 1);
    const quad D = B < 0 ? -Dm : Dm;
    const quad rn = p * (1 + D * D) / 2;
    x = p * (1 - D * D) / 2;
    y = p * D;
    vx = -sqrt(mu * p) * D / rn;
    vy = sqrt(mu * p) / rn;
  }
  for (int k = 0; k < 3; ++k) r[k] = x * P[k] + y * Q[k], v[k] = vx * P[k] + vy * Q[k];
}

}  // namespace rotlie::test
