#pragma once
// Elliptic functions for the exact free-body flow, parametrised by the complementary parameter
// m_c = 1 − m (REFERENCE.md §2.5: passing k = √m loses m_c below the round-off of 1). K comes from
// the arithmetic-geometric mean, sn cn dn from its descending recursion (A&S 16.4) or, for
// m_c below the unit round-off, from the first-order expansion about m = 1 (A&S 16.15); F and Π
// come from Carlson's R_F and R_J written in sn, cn, dn, so that Δ² = cn² + m_c sn² never cancels.
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rotlie::models::elliptic {

/// Boost.Math evaluates double functions in long double by default; the formulas here are
/// already cancellation-free, so double stays double (4× faster, same accuracy: numeric_bench).
using policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

template <class T>
struct jacobi_triple {
  T sn, cn, dn;
};

/// K(m) = π / (2 AGM(1, √m_c)) (A&S 17.6).
template <class T>
T complete_first_kind(const T& mc) {
  using std::abs;
  using std::sqrt;
  T a = 1, b = sqrt(mc);
  for (int i = 0; i < 64 && abs(a - b) > std::numeric_limits<T>::epsilon() * a; ++i) {
    const T next = (a + b) / 2;
    b = sqrt(a * b);
    a = next;
  }
  return boost::math::constants::half_pi<T>() / ((a + b) / 2);
}

/// sn, cn, dn of (u | m) with m = 1 − m_c: the descending AGM for m_c ≥ 1/2, the ascending Landen
/// transformation down to m_c ≤ ε, then the expansion about m = 1. Accurate (relative) for |u| ≤ K/2; callers reduce
/// larger arguments with sn(K − w) = cd w, cn(K − w) = m_c^½ sd w, dn(K − w) = m_c^½ nd w.
template <class T>
jacobi_triple<T> jacobi_functions(const T& u, const T& m, const T& mc) {
  using std::asin;
  using std::cos;
  using std::cosh;
  using std::ldexp;
  using std::sin;
  using std::sqrt;
  using std::tanh;
  const T eps = std::numeric_limits<T>::epsilon();
  if (mc <= eps) {
    // A&S 16.15.1–3 to first order in m_c; the next term is O(m_c² cosh⁴u) ≤ O(m_c) for |u| ≤ K/2
    const T th = tanh(u), sech = 1 / cosh(u), sh = th / sech;
    const T q = mc / 4;
    return {th + q * (th - u * sech * sech), sech - q * th * (sh - u * sech), sech + q * th * (sh + u * sech)};
  }
  if (mc < T(0.5)) {
    // ascending Landen transformation (A&S 16.14): μ₁ = ((1 − k)/(1 + k))² ≈ (m_c/4)², so two or
    // three steps reach the expansion above; 1 − k = m_c/(1 + k) without cancellation
    const T k = sqrt(m), root_mu1 = mc / ((1 + k) * (1 + k)), mu = 4 * k / ((1 + k) * (1 + k));
    const auto j = jacobi_functions(u / (1 + root_mu1), mu, root_mu1 * root_mu1);
    const T dn2 = j.dn * j.dn;
    return {(1 + root_mu1) * j.sn * j.cn / j.dn, (1 + root_mu1) / mu * (dn2 - root_mu1) / j.dn,
            (1 - root_mu1) / mu * (dn2 + root_mu1) / j.dn};
  }
  // A&S 16.4: a₀ = 1, b₀ = √m_c, c₀ = √m; c_{n+1} = c_n²/(4 a_{n+1}) avoids the cancellation a_n − b_n
  std::array<T, 40> a{}, c{};
  a[0] = 1, c[0] = sqrt(m);
  T b = sqrt(mc);
  std::size_t N = 0;
  while (c[N] > eps * a[N] && N + 1 < a.size()) {
    a[N + 1] = (a[N] + b) / 2;
    c[N + 1] = c[N] * c[N] / (4 * a[N + 1]);
    b = sqrt(a[N] * b);
    ++N;
  }
  T phi = ldexp(a[N] * u, static_cast<int>(N));
  for (std::size_t i = N; i > 0; --i) phi = (phi + asin(c[i] / a[i] * sin(phi))) / 2;
  const T s = sin(phi), cn = cos(phi);
  return {s, cn, sqrt(cn * cn + mc * s * s)};
}

/// sn, cn, dn of (u | m) for m_c ≥ 1/2 by the descending Landen (Gauss) transformation (A&S 16.12):
/// μ = ((1 − k')/(1 + k'))², √μ = m/(1 + k')² without cancellation, the functions at u/(1 + √μ) and
/// parameter μ, down to μ ≤ √ε/8 (three levels from m = 1/2 in double), then the first order in μ
/// (A&S 16.13). No inverse sines and one sin, cos in all: the cheap form for the short arguments of a
/// step; every denominator is 1 + √μ sn² with √μ ≤ 0.18, so nothing cancels. Relative error a few ε.
template <class T>
jacobi_triple<T> jacobi_functions_gauss(T u, T m, T mc) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  // the descent, one level at a time (each: √μ, then u/(1 + √μ) at parameter μ), the ascent backwards
  // four levels from m = 3/4 (m_c = 1/4, the callers' least) in double, five in float128; 16 reach m_c
  // near 10⁻⁸, below which the caller takes jacobi_functions
  constexpr int max_levels = 16;
  std::array<T, max_levels> root_mu{};
  int levels = 0;
  const T threshold = sqrt(std::numeric_limits<T>::epsilon()) / 8;
  while (m > threshold && levels < max_levels) {
    const T kc = sqrt(mc), k1_2 = (1 + kc) * (1 + kc), r = m / k1_2;
    root_mu[static_cast<std::size_t>(levels++)] = r;
    u = u / (1 + r), mc = 4 * kc / k1_2, m = r * r;
  }
  const T s = sin(u), c = cos(u), q = m / 4 * (u - s * c);
  jacobi_triple<T> j{s - q * c, c + q * s, 1 - m / 2 * s * s};
  while (levels > 0) {
    const T r = root_mu[static_cast<std::size_t>(--levels)];
    const T s2 = r * j.sn * j.sn, inv = 1 / (1 + s2);
    j = {(1 + r) * j.sn * inv, j.cn * j.dn * inv, (1 - s2) * inv};
  }
  return j;
}

/// F(am u | m) = u recovered from sn, cn, dn with |am u| ≤ π/2 (cn ≥ 0): sn R_F(cn², dn², 1).
template <class T>
T first_kind_from(const jacobi_triple<T>& j) {
  return j.sn * boost::math::ellint_rf(j.cn * j.cn, j.dn * j.dn, T(1), policy());
}

/// Π(am u; n | m) − F(am u | m) = (n/3) sn³ R_J(cn², dn², 1, 1 − n sn²) for cn ≥ 0 (DLMF 19.25.14),
/// with 1 − n sn² given by the caller without cancellation.
template <class T>
T third_minus_first(const jacobi_triple<T>& j, const T& n, const T& one_minus_n_sn2) {
  if (n == 0 || j.sn == 0) return T(0);
  return n / 3 * j.sn * j.sn * j.sn * boost::math::ellint_rj(j.cn * j.cn, j.dn * j.dn, T(1), one_minus_n_sn2, policy());
}

/// Carlson's bound factor (r/4)^(−1/6) for the relative error r = ε of T: the duplications of R_J
/// stop when 4^−m times it times the spread of the arguments falls below A_m (Carlson 1995, eq. 2.21).
template <class T>
const T& carlson_spread_factor() {
  using std::pow;
  static const T factor = pow(std::numeric_limits<T>::epsilon() / 4, T(-1) / 6);
  return factor;
}
// Duplications of R_J: about log₄(max(p, x, y, z) / min of them) + 5 are needed, so 60 serve arguments
// within a ratio of 10³³ of each other; the step's (p ≤ 1 + |n| sn², x, y ≥ 1/4) need fewer than 8.
inline constexpr int carlson_max_duplications = 60;

/// Where carlson_rc_one's series serves: |e| < ε^(1/5)/16 (4.6e-5 in double), where the first term
/// left out, e⁵/11, is below 10⁻⁷ ε.
template <class T>
const T& carlson_rc_series_bound() {
  using std::pow;
  static const T bound = pow(std::numeric_limits<T>::epsilon(), T(1) / 5) / 16;
  return bound;
}

/// The coefficients of R_J's series to the fifth order (Carlson 1995, eq. 2.19): 3/14, 1/6, 9/88,
/// 3/22, 9/52, 3/26, rounded once in T.
template <class T>
struct carlson_rj_series {
  T e2 = T(3) / 14, e3 = T(1) / 6, e22 = T(9) / 88, e4 = T(3) / 22, e23 = T(9) / 52, e5 = T(3) / 26;
};

/// R_C(1, 1 + e) = atan(√e)/√e (e > 0), atanh(√−e)/√−e (e < 0); for small |e| its series
/// 1 − e/3 + e²/5 − e³/7 + e⁴/9 (carlson_rc_series_bound), which the duplications of a step's R_J
/// almost always meet.
template <class T>
T carlson_rc_one(const T& e) {
  using std::abs;
  using std::atan;
  using std::atanh;
  using std::sqrt;
  if (abs(e) < carlson_rc_series_bound<T>()) return 1 - e * (T(1) / 3 - e * (T(1) / 5 - e * (T(1) / 7 - e * (T(1) / 9))));
  const T root_e = sqrt(abs(e));
  return e > 0 ? atan(root_e) / root_e : atanh(root_e) / root_e;
}

/// Carlson's R_J(x, y, z, p) for x, y, z ≥ 0 (at most one of them 0) and p > 0, by duplication and
/// the series to the fifth order (Carlson 1995, Numer. Algorithms 10, 13, eqs. 2.17–2.21; DLMF
/// 19.36.i), R_C(1, 1 + e) = atan(√e)/√e or atanh(√−e)/√−e. Written out (not Boost's) so that the
/// vectorised exact flow (models/src/exact_free_rotation_batch.cpp) can follow it line by line.
template <class T>
T carlson_rj(T x, T y, T z, T p) {
  using std::abs;
  using std::atan;
  using std::atanh;
  using std::sqrt;
  const T A0 = (x + y + z + 2 * p) / 5;
  const T delta = (p - x) * (p - y) * (p - z);
  const T dx = A0 - x, dy = A0 - y, dz = A0 - z;  // X, Y, Z below are these over 4^m A_m
  const T Q = carlson_spread_factor<T>() * std::max(std::max(abs(dx), abs(dy)), std::max(abs(dz), abs(A0 - p)));
  T A = A0, fac = 1, sum = 0;
  for (int k = 0; k < carlson_max_duplications && fac * Q >= abs(A); ++k) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);
    const T lambda = sx * sy + sx * sz + sy * sz;
    const T dm = (sp + sx) * (sp + sy) * (sp + sz);
    const T em = fac * fac * fac * delta / (dm * dm);
    const T rc = carlson_rc_one(em);
    sum = sum + fac * rc / dm;
    A = (A + lambda) * T(0.25), x = (x + lambda) * T(0.25), y = (y + lambda) * T(0.25), z = (z + lambda) * T(0.25);
    p = (p + lambda) * T(0.25), fac = fac * T(0.25);
  }
  const T scale = fac / A;
  const T X = dx * scale, Y = dy * scale, Z = dz * scale, P = -(X + Y + Z) * T(0.5);
  const T XYZ = X * Y * Z, P2 = P * P, P3 = P2 * P;
  const T E2 = X * Y + X * Z + Y * Z - 3 * P2, E3 = XYZ + 2 * E2 * P + 4 * P3, E4 = (2 * XYZ + E2 * P + 3 * P3) * P, E5 = XYZ * P2;
  const carlson_rj_series<T> c;
  const T series = 1 - c.e2 * E2 + c.e3 * E3 + c.e22 * (E2 * E2) - c.e4 * E4 - c.e23 * (E2 * E3) + c.e5 * E5;
  return fac / (A * sqrt(A)) * series + 6 * sum;
}

/// third_minus_first with carlson_rj: the step's form (the vectorised step follows it line by line).
template <class T>
T third_minus_first_carlson(const jacobi_triple<T>& j, const T& n, const T& one_minus_n_sn2) {
  if (n == 0 || j.sn == 0) return T(0);
  return n / 3 * j.sn * j.sn * j.sn * carlson_rj(j.cn * j.cn, j.dn * j.dn, T(1), one_minus_n_sn2);
}

/// sn, cn, dn of u + v from those of u and of v (A&S 16.17.1–3), the denominator 1 − m sn²u sn²v
/// written as cn²u + sn²u dn²v (a sum of squares: it never cancels). Absolute error a few ε.
template <class T>
jacobi_triple<T> jacobi_sum(const jacobi_triple<T>& a, const jacobi_triple<T>& b, const T& m) {
  const T r = 1 / (a.cn * a.cn + a.sn * a.sn * (b.dn * b.dn));
  return {(a.sn * b.cn * b.dn + b.sn * a.cn * a.dn) * r, (a.cn * b.cn - a.sn * b.sn * (a.dn * b.dn)) * r,
          (a.dn * b.dn - m * (a.sn * b.sn) * (a.cn * b.cn)) * r};
}

/// The addition theorem of the integral of the third kind for n ≤ 0, in Jacobi's argument:
/// with D(w) = Π(am w; n | m) − w,
///   D(u + v) − D(u) − D(v) = (n/√κ) atan(√κ P / (1 − n W)),   κ = −n (1 − n)(m − n),
///   P = sn u sn v sn(u+v),   W = [sn²u + sn²v + sn²(u+v) − m P²]/2 ≥ 0,
/// where (1 − n W)² = Π_i (1 − n sn²_i) − κ P² (the three points of the theorem). W is summed as
/// [sn²v + sn²(u+v) + sn²u (cn²v + sn²v dn²(u+v))]/2, every term of one sign, so 1 − n W ≥ 1: the
/// atan stays on its principal branch for every u and v, and nothing cancels.
template <class T>
T third_kind_sum_term(const jacobi_triple<T>& u, const jacobi_triple<T>& v, const jacobi_triple<T>& sum, const T& n,
                      const T& m) {
  using std::atan;
  using std::sqrt;
  if (n == 0) return T(0);
  const T P = u.sn * v.sn * sum.sn;
  const T W = (v.sn * v.sn + sum.sn * sum.sn + u.sn * u.sn * (v.cn * v.cn + v.sn * v.sn * (sum.dn * sum.dn))) / 2;
  const T root_kappa = sqrt(-n * (1 - n) * (m - n));
  return n / root_kappa * atan(root_kappa * P / (1 - n * W));
}

}  // namespace rotlie::models::elliptic
