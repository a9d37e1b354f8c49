#pragma once
// The exact Kepler flow of a relative orbit, r̈ = −GM r/|r|³, for any time step and any orbit
// (elliptic, parabolic, hyperbolic), in universal variables (Danby 1988, §6.9; Battin 1999, §4.5):
// the universal anomaly χ solves
//   F(χ) = σ₀ χ² C(αχ²) + (1 − αr₀) χ³ S(αχ²) + r₀ χ − √GM Δt = 0,   α = 2/r₀ − v₀²/GM, σ₀ = r₀·v₀/√GM,
// with Stumpff's C(z) = (1 − cos √z)/z and S(z) = (√z − sin √z)/√z³ (series near z = 0); then
// r = f r₀ + g v₀, v = ḟ r₀ + ġ v₀ with Lagrange's f, g. The flow keeps r × v (f ġ − ḟ g = 1) and is
// the drift of a Wisdom–Holman split.
//
// The solver cannot fail on valid input: F′(χ) = |r(χ)| > 0, so F increases and its one root lies
// between 0 and a bound that is known for an ellipse (after whole periods are taken off the step,
// χ = √a ΔE with |ΔE| < 2π) and found by doubling otherwise. Newton's iterates are kept inside that
// bracket, which every evaluation narrows; a step that leaves it, or one not at most half the step
// before last, is replaced by a bisection (geometric while the bracket spans more than a factor 4). A value of F that
// overflows (cosh of a huge hyperbolic anomaly) lies beyond the root, as F grows without bound. If
// the end state itself overflows in f and g, the step is split in two.
//
// One case leaves the universal form: a hyperbola entered from far out (|tanh H₀| > 0.8, inbound in the
// step's direction of time) over a step reaching halfway to the pericentre or beyond. There σ₀χ²C and
// (1 − αr₀)χ³S cancel by about e^{2 min(|H₀|, |ΔH|)}, and the step goes by the classical elements
// instead (inbound_hyperbola). Steps that worked before are unchanged; ellipses whose Newton iterates
// would leave the bracket now bisect and may differ in the last bits.
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
    // cosh and sinh overflow past s ≈ log(max): C, S are then +inf, which the solver reads as
    // "beyond the root"
    const T s = sqrt(-z);
    C = (cosh(s) - 1) / -z;
    S = (sinh(s) - s) / (s * -z);
  }
}

/// The universal Kepler equation of one start: F(χ) and F′(χ) = |r(χ)|.
template <class T>
struct universal_equation {
  T r0, sigma, alpha, beta, tau;  // β = 1 − αr₀, τ = √GM Δt

  void at(const T& chi, T& F, T& r) const {
    T C, S;
    const T z = alpha * chi * chi;
    stumpff(z, C, S);
    const T chi2 = chi * chi;
    F = sigma * chi2 * C + beta * chi2 * chi * S + r0 * chi - tau;
    r = sigma * chi * (1 - z * S) + beta * chi2 * C + r0;
  }
};

/// The root of F, from the guess chi, inside [lo, hi] with F(lo) ≤ 0 ≤ F(hi).
template <class T>
T universal_anomaly(const universal_equation<T>& eq, T chi, T lo, T hi) {
  using std::abs;
  using std::isfinite;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  // the last two Newton steps: a step must be at most half the one before last, else Newton is
  // wandering or crawling and a bisection takes over
  T step1 = std::numeric_limits<T>::infinity(), step2 = step1;
  // halves a bracket of any width: arithmetic when narrow, geometric when it spans orders of magnitude
  const auto middle = [](const T& a, const T& b) {
    if (a > 0 && b > 4 * a) return sqrt(a) * sqrt(b);
    if (b < 0 && a < 4 * b) return -(sqrt(-a) * sqrt(-b));
    return a + (b - a) / 2;
  };
  // far more than bisection over the whole exponent range of T needs
  const int max_iterations = 8 * (std::numeric_limits<T>::digits + std::numeric_limits<T>::max_exponent);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    T F, r;
    eq.at(chi, F, r);
    if (!isfinite(F) || !isfinite(r)) {  // an overflow: F grows without bound, so the root is nearer 0
      if (chi > 0 && chi < hi) hi = chi;
      if (chi < 0 && chi > lo) lo = chi;
      chi = middle(lo, hi);
      step1 = step2 = hi - lo;
      continue;
    }
    if (F == 0) return chi;
    if (F < 0 && chi > lo) lo = chi;  // the guess may lie outside the bracket: only narrow it
    if (F > 0 && chi < hi) hi = chi;
    const T delta = F / r;
    const T next = chi - delta;
    if (abs(delta) <= 4 * eps * abs(chi)) return next;  // converged (the test and update of plain Newton)
    const T width = hi - lo;
    if (!(width > 4 * eps * abs(chi))) return lo + width / 2;  // the bracket is one point to round-off
    if (next > lo && next < hi && abs(delta) <= step2 / 2) {
      chi = next;
      step2 = step1, step1 = abs(delta);
    } else {
      chi = middle(lo, hi);
      step1 = step2 = width;
    }
  }
  throw std::logic_error("Kepler drift: the universal anomaly did not converge inside its bracket");
}

/// A hyperbola entered from far out, in its classical elements: the pericentre direction P, Q = ĥ × P,
/// the hyperbolic anomaly H₀ = asinh(r₀·Q / √(|a| p)), then e sinh H − H = e sinh H₀ − H₀ + n Δt solved
/// for H (monotonic: safeguarded Newton), r = |a| ((e − cosh H) P + √(e² − 1) sinh H Q). Here the
/// universal form's σ₀χ²C and (1 − αr₀)χ³S cancel by e^{2|H₀|}, these steps by no more than the
/// problem's own condition.
template <class T>
bool inbound_hyperbola(vec3<T>& r, vec3<T>& v, const T& GM, const T& dt) {
  using std::abs;
  using std::asinh;
  using std::cosh;
  using std::isfinite;
  using std::sinh;
  using std::sqrt;
  const T r0 = sqrt(dot(r, r)), rv = dot(r, v), v2 = dot(v, v);
  const vec3<T> h{r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2], r[0] * v[1] - r[1] * v[0]};
  const T hn = sqrt(dot(h, h)), p = hn * hn / GM, A = 1 / (v2 / GM - 2 / r0);
  // so far out that r × v is lost to round-off (the orbit radial to working precision): no frame
  if (!(hn > 0) || !isfinite(hn) || !(A > 0) || !isfinite(A)) return false;
  const T e = sqrt(1 + p / A), e_minus_1 = (p / A) / (1 + e);
  vec3<T> P, Q;
  for (std::size_t k = 0; k < 3; ++k) P[k] = (v2 - GM / r0) * r[k] - rv * v[k];
  const T Pn = sqrt(dot(P, P));
  for (std::size_t k = 0; k < 3; ++k) P[k] /= Pn;
  Q = {(h[1] * P[2] - h[2] * P[1]) / hn, (h[2] * P[0] - h[0] * P[2]) / hn, (h[0] * P[1] - h[1] * P[0]) / hn};
  const T b = sqrt(A * p);  // |a| √(e² − 1)
  // e sinh H − H = (e − 1) H + e (sinh H − H), the second by its series where H is small
  const auto kepler = [&](const T& H) {
    if (abs(H) > T(0.5)) return e * sinh(H) - H;
    T term = H * H * H / 6, sum = 0;
    for (int k = 1; k < 40 && abs(term) > std::numeric_limits<T>::epsilon() * abs(sum) / 4; ++k) sum += term, term *= H * H / T((2 * k + 2) * (2 * k + 3));
    return e_minus_1 * H + e * (sum + term);
  };
  const T H0 = asinh(dot(r, Q) / b);
  const T M = kepler(H0) + sqrt(GM / (A * A * A)) * dt;
  // the root of an odd increasing function: |H| ≤ asinh(|M| / (e − 1)) and ≤ (6|M|/e)^⅓ + |M|
  const T m = abs(M);
  T lo = 0, hi = std::min(asinh(m / e_minus_1), std::cbrt(static_cast<double>(6 * m / e)) + m) * T(1.01) + std::numeric_limits<T>::min();
  T H = std::min(hi / 2, asinh(m / e));
  for (int k = 0; k < 8 * std::numeric_limits<T>::digits; ++k) {
    const T g = kepler(H) - m;
    if (isfinite(g) && g < 0) lo = H; else hi = H;
    if (!isfinite(g) || g == 0) { if (g == 0) break; H = lo + (hi - lo) / 2; continue; }
    const T next = H - g / (e * cosh(H) - 1);
    if (abs(next - H) <= 4 * std::numeric_limits<T>::epsilon() * abs(H)) { H = next; break; }
    H = (next > lo && next < hi) ? next : lo + (hi - lo) / 2;
    if (!(hi - lo > 4 * std::numeric_limits<T>::epsilon() * hi)) break;
  }
  if (M < 0) H = -H;
  const T sh = sinh(H / 2), rn = A * e_minus_1 + 2 * A * e * sh * sh;
  const T x = A * e_minus_1 - 2 * A * sh * sh, y = b * sinh(H);
  const T vx = -sqrt(GM * A) * sinh(H) / rn, vy = sqrt(GM * p) * cosh(H) / rn;
  if (!isfinite(x) || !isfinite(y) || !isfinite(vx) || !isfinite(vy) || !(Pn > 0)) return false;
  for (std::size_t k = 0; k < 3; ++k) r[k] = x * P[k] + y * Q[k], v[k] = vx * P[k] + vy * Q[k];
  return true;
}

}  // namespace kepler_detail

/// Advances (r, v) along the Kepler orbit of gravitational parameter GM by dt (any sign).
template <class T>
void kepler_drift(vec3<T>& r, vec3<T>& v, const T& GM, const T& dt) {
  using kepler_detail::universal_anomaly;
  using kepler_detail::universal_equation;
  using kepler_detail::stumpff;
  using std::abs;
  using std::acos;
  using std::isfinite;
  using std::sqrt;
  const T r0 = sqrt(dot(r, r)), rv = dot(r, v), v2 = dot(v, v), sqrt_mu = sqrt(GM);
  if (!(r0 > 0) || !isfinite(r0) || !isfinite(v2) || !(GM > 0) || !isfinite(GM) || !isfinite(dt))
    throw std::invalid_argument("Kepler drift: the separation must be positive and finite, GM positive, the step finite");
  const T alpha = 2 / r0 - v2 / GM;  // 1/a
  T time = dt;
  T chi_limit = 0;  // an ellipse's bound on |χ|: one turn of the eccentric anomaly
  if (alpha > 0) {  // an ellipse: whole periods change nothing
    const T period = 2 * acos(T(-1)) / (alpha * sqrt(alpha) * sqrt_mu);
    using std::round;
    time -= period * round(dt / period);
    chi_limit = 2 * acos(T(-1)) / sqrt(alpha);
  }
  const T sigma = rv / sqrt_mu;  // r₀ v_r0 / √GM
  const universal_equation<T> eq{r0, sigma, alpha, 1 - alpha * r0, sqrt_mu * time};
  if (alpha < 0 && time * sigma < 0 && abs(sigma) * sqrt(-alpha) > T(0.8) * (1 - alpha * r0)) {
    // inbound on a hyperbola with |tanh H₀| > 0.8 (r₀ well beyond the pericentre): the cancellation
    // grows as e^{2 min(|H₀|, |ΔH|)}, so a step reaching halfway in time to the pericentre or beyond goes
    // by the classical elements (the universal form below if r × v is lost to round-off)
    using std::atanh;
    const T beta = 1 - alpha * r0, u = abs(sigma) * sqrt(-alpha) / beta;
    const T chi_p = -sigma / beta * (u < 1 ? atanh(u) / u : T(0));
    const universal_equation<T> to_pericentre{r0, sigma, alpha, beta, 0};
    T tau_p = 0, r_p;
    to_pericentre.at(chi_p, tau_p, r_p);
    if (!(u < 1) || !(abs(sqrt_mu * time) < tau_p * (time > 0 ? 1 : -1) / 2))
      if (kepler_detail::inbound_hyperbola(r, v, GM, time)) return;
  }
  // first guess: the mean motion's angle for an ellipse, else the straight line
  const T guess = alpha > 0 ? sqrt_mu * time * alpha : sqrt_mu * time / r0;
  T chi = 0;
  if (guess != 0) {  // else the step is below round-off of the position: χ = 0 to working precision
    // the root has the sign of the step (F(0) = −τ): a bracket [0, far] or [−far, 0], narrowed below
    const T sign = time > 0 ? T(1) : T(-1);
    T near = 0, far = 0;
    if (alpha > 0) {
      far = sign * chi_limit;  // F(±2π√a) = ±(one period's τ) − τ, |τ| at most half a period's
    } else {
      // double from the guess until F changes sign or overflows; the last point short of it is the near end
      far = guess;
      for (;;) {
        T F, rx;
        eq.at(far, F, rx);
        if (!isfinite(F) || sign * F >= 0) break;
        near = far;
        if (!isfinite(2 * far)) break;  // unreachable before F overflows; keeps the loop finite
        far *= 2;
      }
    }
    chi = sign > 0 ? universal_anomaly(eq, guess, near, far) : universal_anomaly(eq, guess, far, near);
  }
  T C = 0, S = 0;
  const T z = alpha * chi * chi;
  stumpff(z, C, S);
  const T chi2 = chi * chi;
  const T f = 1 - chi2 / r0 * C, g = time - chi2 * chi / sqrt_mu * S;
  vec3<T> r1;
  for (std::size_t k = 0; k < 3; ++k) r1[k] = f * r[k] + g * v[k];
  const T r1n = sqrt(dot(r1, r1));
  const T fdot = sqrt_mu / (r1n * r0) * (z * chi * S - chi), gdot = 1 - chi2 / r1n * C;
  if (!isfinite(f) || !isfinite(g) || !isfinite(fdot) || !isfinite(gdot) || !isfinite(r1n)) {
    // a hyperbolic step so long that f and g overflow although the end does not: two halves
    if (!(abs(dt) / 2 < abs(dt))) throw std::domain_error("Kepler drift: the state overflows");
    const T half = dt / 2;
    kepler_drift(r, v, GM, half);
    kepler_drift(r, v, GM, dt - half);
    return;
  }
  for (std::size_t k = 0; k < 3; ++k) v[k] = fdot * r[k] + gdot * v[k];
  r = r1;
}


}  // namespace rotlie::models
