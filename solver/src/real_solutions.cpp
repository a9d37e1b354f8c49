#include "rotlie/solver/real_solutions.hpp"

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/real.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <complex>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/residue_field.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

using lie::coefficient_polynomial;
using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }
cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

// A bivariate polynomial as rows c[i][j] of u^i v^j, evaluated first in u (once per root u), then in v
// by Horner: exactly (T = cl_RA) or in floating point of a fixed precision (T = cl_F).
template <class T>
class bivariate_in {
 public:
  bivariate_in(const coefficient_polynomial& p, int u, int v, const cln::float_format_t& format = cln::float_format_t(0))
      : zero_(convert(0, format)), one_(convert(1, format)) {
    for (const auto& t : p.terms()) {
      const auto e = coefficient_polynomial::unpack(t.key);
      const auto i = static_cast<std::size_t>(e[static_cast<std::size_t>(u)]);
      const auto j = static_cast<std::size_t>(e[static_cast<std::size_t>(v)]);
      if (c_.size() <= i) c_.resize(i + 1);
      if (c_[i].size() <= j) c_[i].resize(j + 1, zero_);
      c_[i][j] = convert(t.c, format);
      degree_v_ = std::max(degree_v_, static_cast<int>(j));
    }
  }
  int degree_v() const { return degree_v_; }
  /// (value, magnitude) at u fixed, as polynomials in v: value Σ c_ij u^i v^j and Σ |c_ij| max(1,|u|)^i.
  struct in_v {
    std::vector<T> value, magnitude;
  };
  in_v at_u(const T& x) const {
    in_v r{std::vector<T>(static_cast<std::size_t>(degree_v_) + 1, zero_), std::vector<T>(static_cast<std::size_t>(degree_v_) + 1, zero_)};
    const T ax = cln::max(one_, cln::abs(x));
    for (std::size_t i = c_.size(); i-- > 0;)
      for (std::size_t j = 0; j < r.value.size(); ++j) {
        const T& c = j < c_[i].size() ? c_[i][j] : zero_;
        r.value[j] = r.value[j] * x + c;
        r.magnitude[j] = r.magnitude[j] * ax + cln::abs(c);
      }
    return r;
  }
  /// The degree in v at the root u* known to lie in (x − h, x + h): leading coefficients c_j(u) that
  /// change sign (or vanish) across that interval vanish at u* and are dropped.
  int degree_v_at_root(const T& x, const T& h) const {
    const auto coefficient_at = [&](int j, const T& at) {
      T s = zero_;
      for (std::size_t i = c_.size(); i-- > 0;) s = s * at + (static_cast<std::size_t>(j) < c_[i].size() ? c_[i][static_cast<std::size_t>(j)] : zero_);
      return s;
    };
    int d = degree_v_;
    const auto sign = [](const T& y) { return cln::zerop(y) ? 0 : (cln::minusp(y) ? -1 : 1); };
    while (d > 0 && sign(coefficient_at(d, x - h)) * sign(coefficient_at(d, x + h)) <= 0) --d;
    return d;
  }
  T horner(const std::vector<T>& c, const T& y) const {
    T s = zero_;
    for (auto it = c.rbegin(); it != c.rend(); ++it) s = s * y + *it;
    return s;
  }
  /// |e(x, y)| when it is below tolerance × (1 + size of the terms), i.e. (x, y) is a root to that width.
  std::optional<T> vanishes(const in_v& at_x, const T& y, const T& tolerance) const {
    const T ay = cln::max(one_, cln::abs(y));
    const T r = cln::abs(horner(at_x.value, y));
    if (r <= tolerance * (one_ + horner(at_x.magnitude, ay))) return r;
    return std::nullopt;
  }
  T convert(const cln::cl_RA& x) const { return convert(x, format_of(one_)); }

 private:
  static cln::float_format_t format_of(const cln::cl_RA&) { return cln::float_format_t(0); }
  static cln::float_format_t format_of(const cln::cl_F& x) { return cln::float_format(x); }
  static T convert(const cln::cl_RA& x, const cln::float_format_t& format) {
    if constexpr (std::is_same_v<T, cln::cl_F>)
      return cln::cl_float(x, format);
    else
      return x;
  }
  T zero_, one_;
  std::vector<std::vector<T>> c_;
  int degree_v_ = 0;
};
using bivariate = bivariate_in<cln::cl_RA>;
using float_bivariate_rows = bivariate_in<cln::cl_F>;

// Real roots of the eliminant, isolated exactly. When the cheap modular certificate of
// square-freeness fails, gcd(R, R') splits R into its square-free part and its repeated part (whose
// roots are where back-substitution's uniqueness argument does not hold).
struct eliminant_roots {
  rational_polynomial square_free;
  rational_polynomial multiple;  ///< square-free, its roots are the multiple roots of the eliminant (1 if none)
  std::vector<root_interval> intervals;
};

eliminant_roots isolate(const rational_polynomial& eliminant) {
  eliminant_roots out;
  out.multiple = rational_polynomial({1});
  if (square_free_certified_mod_prime(eliminant)) {
    out.square_free = eliminant;
  } else {
    const rational_polynomial g = modular_gcd(eliminant, eliminant.derivative());
    out.square_free = quotient(eliminant, g);
    if (g.degree() >= 1) out.multiple = quotient(g, modular_gcd(g, g.derivative()));
  }
  out.intervals = isolate_real_roots_of_square_free(out.square_free);
  return out;
}

// The pairing method: the real roots v of the other resultant, every pair with the given u tested.
std::vector<real_point> pair_roots(const coefficient_polynomial& e1, const coefficient_polynomial& e2, int u, int v,
                                   const std::vector<cln::cl_RA>& us, int digits) {
  std::vector<cln::cl_RA> vs;
  const eliminant_roots in_v = isolate(resultant_in(e1, e2, u, v));
  const root_polisher polish_v(in_v.square_free, digits);
  for (const auto& r : in_v.intervals) vs.push_back(polish_v.polish(r));
  const bivariate b1(e1, u, v), b2(e2, u, v);
  // A true solution leaves |e| ≲ deg·|terms|·width; any other pair leaves a fixed nonzero algebraic
  // number, far above 10^-(digits+3) of the size of the terms.
  const cln::cl_RA tolerance = ten_to_minus(digits + 3);
  std::vector<real_point> points;
  for (const auto& x : us) {
    const auto f1 = b1.at_u(x), f2 = b2.at_u(x);
    for (const auto& y : vs) {
      const auto r1 = b1.vanishes(f1, y, tolerance);
      if (!r1) continue;
      if (const auto r2 = b2.vanishes(f2, y, tolerance)) points.push_back({x, y, cln::max(*r1, *r2)});
    }
  }
  return points;
}

std::vector<cln::cl_RA> polished_roots(const eliminant_roots& in_u, int digits) {
  const root_polisher polisher(in_u.square_free, digits);
  std::vector<cln::cl_RA> us;
  for (const auto& r : in_u.intervals) us.push_back(polisher.polish(r));
  return us;
}

// All complex roots of a univariate polynomial (exact coefficients, index = power), in double, as the
// eigenvalues of its companion matrix: starting points only, every one is polished and checked.
template <class T>
std::vector<std::complex<double>> complex_roots(const std::vector<T>& exact) {
  std::vector<double> c;
  for (const auto& x : exact) c.push_back(cln::double_approx(x));
  while (!c.empty() && c.back() == 0) c.pop_back();
  if (c.size() < 2) return {};
  const auto n = static_cast<Eigen::Index>(c.size() - 1);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 1; i < n; ++i) companion(i, i - 1) = 1;
  for (Eigen::Index i = 0; i < n; ++i) companion(i, n - 1) = -c[static_cast<std::size_t>(i)] / c.back();
  const Eigen::VectorXcd eigenvalues = companion.eigenvalues();
  return {eigenvalues.begin(), eigenvalues.end()};
}

// e1, e2 and their derivatives in u, as rows in floating point, for back-substitution.
struct float_system {
  float_system(const coefficient_polynomial& p1, const coefficient_polynomial& p2, int u, int v,
               const cln::float_format_t& format)
      : e1(p1, u, v, format), e2(p2, u, v, format), e1_u(p1.derivative(u), u, v, format), e2_u(p2.derivative(u), u, v, format) {}
  float_bivariate_rows e1, e2, e1_u, e2_u;
};

// The common root above a simple root u0 of the eliminant (certified to width/2), which is unique
// and real. Starting points: every root of either equation at u0 (companion matrices, double
// precision), best first by how well the other equation vanishes there. Each is polished by Newton's
// method in v on the equation with the larger slope, then by Newton's method on (e1, e2) in (u, v),
// whose Jacobian is regular at a simple intersection: v at u0 alone would carry u0's error times
// dv/du. Kept when u stays within width/2 of u0 and both equations vanish to 10^-(digits+3) of
// the size of their terms, all in floating point of digits + 30 digits.
std::optional<real_point> common_root_above(const float_system& f, const cln::cl_RA& u0, int digits) {
  const cln::float_format_t format = cln::float_format(digits + 30);
  const cln::cl_F tolerance = cln::cl_float(ten_to_minus(digits + 3), format);
  const cln::cl_F converged = cln::cl_float(ten_to_minus(digits + 12), format);
  const cln::cl_F zero = cln::cl_float(0, format), one = cln::cl_float(1, format);
  const cln::cl_F x0 = cln::cl_float(u0, format);
  const cln::cl_F half_width = cln::cl_float(ten_to_minus(digits + 10) / 2, format);
  std::array<float_bivariate_rows::in_v, 2> at{f.e1.at_u(x0), f.e2.at_u(x0)};
  // Coefficients that vanish at the exact root are zero, not tiny: else they add roots near infinity.
  at[0].value.resize(static_cast<std::size_t>(f.e1.degree_v_at_root(x0, half_width)) + 1);
  at[1].value.resize(static_cast<std::size_t>(f.e2.degree_v_at_root(x0, half_width)) + 1);
  const auto derivative = [&](const std::vector<cln::cl_F>& c) {
    std::vector<cln::cl_F> d;
    for (std::size_t j = 1; j < c.size(); ++j) d.push_back(c[j] * cln::cl_float(cln::cl_I(static_cast<long>(j)), format));
    return d;
  };
  const auto horner = [&](const std::vector<cln::cl_F>& c, const cln::cl_F& y) {
    cln::cl_F r = zero;
    for (auto it = c.rbegin(); it != c.rend(); ++it) r = r * y + *it;
    return r;
  };
  const std::array<std::vector<cln::cl_F>, 2> slope{derivative(at[0].value), derivative(at[1].value)};
  std::vector<std::pair<double, double>> starts;  // (relative |other| + |imaginary part|, v)
  for (std::size_t source = 0; source < 2; ++source) {
    const auto& other = at[1 - source];
    for (const auto& z : complex_roots(at[source].value)) {
      const double y = z.real();
      double value = 0, size = 0;
      for (std::size_t j = other.value.size(); j-- > 0;) {
        value = value * y + cln::double_approx(other.value[j]);
        size = size * std::max(1.0, std::abs(y)) + cln::double_approx(other.magnitude[j]);
      }
      starts.push_back({std::abs(value) / (1 + size) + std::abs(z.imag()) / (1 + std::abs(y)), y});
    }
  }
  std::sort(starts.begin(), starts.end());
  for (const auto& [score, start] : starts) {
    if (score > 1e-3) break;  // far from a common root: the remaining starts are worse
    const cln::cl_F y0 = cln::cl_float(cln::rational(cln::cl_DF(start)), format);
    cln::cl_F y = y0;
    bool newton_converged = false;
    for (int iteration = 0; iteration < 60 && !newton_converged; ++iteration) {
      const cln::cl_F s0 = slope[0].empty() ? zero : horner(slope[0], y);
      const cln::cl_F s1 = slope[1].empty() ? zero : horner(slope[1], y);
      // Slopes relative to each equation's own size: one may be a large multiple of a small factor.
      const cln::cl_F ay = cln::max(one, cln::abs(y));
      const cln::cl_F size0 = one + horner(at[0].magnitude, ay), size1 = one + horner(at[1].magnitude, ay);
      const std::size_t e = cln::abs(s0) / size0 >= cln::abs(s1) / size1 ? 0 : 1;
      const cln::cl_F& s = e == 0 ? s0 : s1;
      if (cln::zerop(s)) break;
      const cln::cl_F step = horner(at[e].value, y) / s;
      y = y - step;
      newton_converged = cln::abs(step) <= converged * (one + cln::abs(y));
    }
    // Polishing only: a start that runs away is not a root here (e.g. a point at infinity).
    if (!newton_converged || cln::abs(y - y0) > cln::cl_float(cln::cl_RA(1) / 10000, format) * (one + cln::abs(y0))) continue;
    cln::cl_F x = x0;
    for (int iteration = 0; iteration < 8; ++iteration) {
      const auto v1 = f.e1.at_u(x), v2 = f.e2.at_u(x), u1 = f.e1_u.at_u(x), u2 = f.e2_u.at_u(x);
      const cln::cl_F a = horner(u1.value, y), b = horner(derivative(v1.value), y);
      const cln::cl_F c = horner(u2.value, y), d = horner(derivative(v2.value), y);
      const cln::cl_F det = a * d - b * c;
      if (cln::zerop(det)) break;
      const cln::cl_F r1 = horner(v1.value, y), r2 = horner(v2.value, y);
      const cln::cl_F dx = (d * r1 - b * r2) / det, dy = (a * r2 - c * r1) / det;
      x = x - dx;
      y = y - dy;
      if (cln::abs(dx) <= converged * (one + cln::abs(x)) && cln::abs(dy) <= converged * (one + cln::abs(y))) break;
    }
    if (cln::abs(x - x0) > half_width * 2) continue;  // another intersection: not this root of R
    const auto v1 = f.e1.at_u(x), v2 = f.e2.at_u(x);
    const auto r1 = f.e1.vanishes(v1, y, tolerance);
    if (!r1) continue;
    const auto r2 = f.e2.vanishes(v2, y, tolerance);
    if (!r2) continue;
    return real_point{cln::rational(x), cln::rational(y), cln::rational(cln::max(*r1, *r2))};
  }
  return std::nullopt;
}

// The simplest rational in [lo, hi] (smallest denominator), by continued fractions.
cln::cl_RA simplest_rational_between(const cln::cl_RA& lo, const cln::cl_RA& hi) {
  if (cln::minusp(hi)) return -simplest_rational_between(-hi, -lo);
  if (!cln::plusp(lo)) return 0;
  const cln::cl_I floor = cln::floor1(lo);
  if (floor + 1 <= hi || floor == lo) return floor == lo ? cln::cl_RA(floor) : cln::cl_RA(floor + 1);
  // lo, hi in (floor, floor + 1): recurse on the reciprocals of the fractional parts
  return floor + cln::recip(simplest_rational_between(cln::recip(hi - floor), cln::recip(lo - floor)));
}

// Every real common root above a rational u = r, exactly: the real roots of g = gcd(e1(r, ·),
// e2(r, ·)) over Q, certified and polished.
std::vector<real_point> common_roots_above_rational(const coefficient_polynomial& e1, const coefficient_polynomial& e2,
                                                    int u, int v, const cln::cl_RA& r, int digits) {
  const auto at = [&](const coefficient_polynomial& e) {
    const coefficient_polynomial p = e.substitute(u, r);
    std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(p.degree(v), 0)) + 1, 0);
    for (const auto& t : p.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(v)])] = t.c;
    return rational_polynomial(std::move(c));
  };
  const rational_polynomial p1 = at(e1), p2 = at(e2);
  std::vector<real_point> points;
  // One equation may hold the whole line u = r (a factor u − r): then the other alone decides.
  if (p1.is_zero() && p2.is_zero()) throw std::logic_error("both equations hold the line u = r: the shared-factor test missed it");
  const rational_polynomial g = p1.is_zero() ? p2 : p2.is_zero() ? p1 : modular_gcd(p1, p2);
  if (g.degree() < 1) return points;
  const rational_polynomial square_free = quotient(g, modular_gcd(g, g.derivative()));
  const root_polisher polisher(square_free, digits);
  for (const auto& interval : isolate_real_roots_of_square_free(square_free))
    points.push_back({r, polisher.polish(interval), 0});
  return points;
}

// Every real common root above an irrational multiple root α of R: g = gcd(e1(α, ·), e2(α, ·)),
// computed exactly in Q(α) (residue_field), made square-free there, and its real roots found at
// α's real value (known to 10^-(digits+30)) by Newton's method in floating point. nullopt when a
// step does not conclude (the caller pairs instead).
std::optional<std::vector<real_point>> common_roots_above_algebraic(const coefficient_polynomial& e1,
                                                                    const coefficient_polynomial& e2, int u, int v,
                                                                    const eliminant_roots& in_u,
                                                                    const root_interval& interval, int digits) {
  const root_polisher fine(in_u.square_free, digits + 20);
  const cln::cl_RA alpha = fine.polish(interval);  // within 10^-(digits+30)/2
  const cln::cl_RA half_width = ten_to_minus(digits + 30) / 2;
  residue_field field(in_u.multiple, alpha - half_width, alpha + half_width);
  const auto coefficients_in_v = [&](const coefficient_polynomial& e) {
    std::vector<rational_polynomial> out;
    for (int j = 0; j <= e.degree(v); ++j) {
      const coefficient_polynomial cj = e.coefficient(v, j);
      std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(cj.degree(u), 0)) + 1, 0);
      for (const auto& t : cj.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] = t.c;
      out.push_back(field.reduce(rational_polynomial(std::move(c))));
    }
    return out;
  };
  std::vector<real_point> points;
  auto g = field.gcd_in_v(coefficients_in_v(e1), coefficients_in_v(e2));
  if (g.size() <= 1) return points;  // coprime above α: no common root
  std::vector<rational_polynomial> slope;
  for (std::size_t j = 1; j < g.size(); ++j) slope.push_back(g[j] * rational_polynomial({cln::cl_RA(static_cast<long>(j))}));
  const auto repeated = field.gcd_in_v(g, slope);
  if (repeated.size() > 1) g = field.quotient_in_v(g, repeated);
  // g's coefficients at α, in floating point; its real roots are simple now.
  const cln::float_format_t format = cln::float_format(digits + 30);
  const cln::cl_F a = cln::cl_float(alpha, format), zero = cln::cl_float(0, format), one = cln::cl_float(1, format);
  std::vector<cln::cl_F> value, derivative;
  for (const auto& c : g) {
    cln::cl_F x = zero;
    for (auto it = c.coefficients().rbegin(); it != c.coefficients().rend(); ++it) x = x * a + cln::cl_float(*it, format);
    value.push_back(x);
  }
  for (std::size_t j = 1; j < value.size(); ++j) derivative.push_back(value[j] * cln::cl_float(cln::cl_I(static_cast<long>(j)), format));
  const auto horner = [&](const std::vector<cln::cl_F>& c, const cln::cl_F& y) {
    cln::cl_F r = zero;
    for (auto it = c.rbegin(); it != c.rend(); ++it) r = r * y + *it;
    return r;
  };
  const cln::cl_F converged = cln::cl_float(ten_to_minus(digits + 15), format);
  const cln::cl_F tolerance = cln::cl_float(ten_to_minus(digits + 3), format);
  const float_bivariate_rows b1(e1, u, v, format), b2(e2, u, v, format);
  const auto at1 = b1.at_u(a), at2 = b2.at_u(a);
  for (const auto& z : complex_roots(value)) {
    if (std::abs(z.imag()) > 1e-6 * (1 + std::abs(z.real()))) continue;  // a conjugate pair
    cln::cl_F y = cln::cl_float(cln::rational(cln::cl_DF(z.real())), format);
    bool newton_converged = false;
    for (int iteration = 0; iteration < 60 && !newton_converged; ++iteration) {
      const cln::cl_F s = horner(derivative, y);
      if (cln::zerop(s)) break;
      const cln::cl_F step = horner(value, y) / s;
      y = y - step;
      newton_converged = cln::abs(step) <= converged * (one + cln::abs(y));
    }
    if (!newton_converged) return std::nullopt;
    const auto r1 = b1.vanishes(at1, y, tolerance), r2 = b2.vanishes(at2, y, tolerance);
    if (!r1 || !r2) return std::nullopt;  // g's root must be a common root: else something is off
    points.push_back({alpha, cln::rational(y), cln::rational(cln::max(*r1, *r2))});
  }
  return points;
}

// Back-substitution at every simple real root of the eliminant (exactly one common root above it,
// real); the multiple roots are set aside in `multiple_roots` and searched without that promise.
// nullopt when a simple root yields nothing and is not a point at infinity: the caller then pairs.
std::optional<std::vector<real_point>> back_substitute(const coefficient_polynomial& e1, const coefficient_polynomial& e2,
                                                       int u, int v, const eliminant_roots& in_u, int digits,
                                                       std::vector<cln::cl_RA>& multiple_roots) {
  const float_system system(e1, e2, u, v, cln::float_format(digits + 30));
  const cln::cl_RA width = ten_to_minus(digits + 10);
  // Where both leading coefficients in v vanish, R vanishes for a point at infinity; R square-free
  // there leaves no finite solution above that root. Those roots are the roots of gcd(lc1, lc2).
  const auto leading = [&](const coefficient_polynomial& e) {
    const coefficient_polynomial lc = e.coefficient(v, e.degree(v));
    std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(lc.degree(u), 0)) + 1, 0);
    for (const auto& t : lc.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] = t.c;
    return rational_polynomial(std::move(c));
  };
  const rational_polynomial at_infinity = gcd(leading(e1), leading(e2));
  const auto root_of = [&](const rational_polynomial& q, const cln::cl_RA& x) {
    return q.degree() >= 1 && cln::signum(q(x - width / 2)) * cln::signum(q(x + width / 2)) <= 0;
  };
  const root_polisher polisher(in_u.square_free, digits);
  std::vector<real_point> points;
  for (const auto& interval : in_u.intervals) {
    const cln::cl_RA u0 = polisher.polish(interval);  // certified to width/2
    if (root_of(in_u.multiple, u0)) {
      // A rational multiple root (often a point at infinity, u = 0 or 1/2 here) is solved exactly:
      // the common roots above it are those of gcd(e1(r, ·), e2(r, ·)) over Q. Others are paired.
      if (const auto r = simplest_rational_between(u0 - width / 2, u0 + width / 2); cln::zerop(in_u.multiple(r))) {
        for (auto& p : common_roots_above_rational(e1, e2, u, v, r, digits)) points.push_back(std::move(p));
        continue;
      }
      if (auto found = common_roots_above_algebraic(e1, e2, u, v, in_u, interval, digits)) {
        for (auto& p : *found) points.push_back(std::move(p));
        continue;
      }
      multiple_roots.push_back(u0);
      continue;
    }
    if (const auto found = common_root_above(system, u0, digits))
      points.push_back(*found);
    else if (!root_of(at_infinity, u0))
      return std::nullopt;
  }
  return points;
}

// A common factor free of v divides the contents of both equations (their coefficients in v).
bool share_factor_in_u(const coefficient_polynomial& e1, const coefficient_polynomial& e2, int u, int v) {
  const auto content = [&](const coefficient_polynomial& e) {
    rational_polynomial g;
    for (int j = 0; j <= e.degree(v); ++j) {
      const coefficient_polynomial cj = e.coefficient(v, j);
      if (cj.is_zero()) continue;
      std::vector<cln::cl_RA> c(static_cast<std::size_t>(cj.degree(u)) + 1, 0);
      for (const auto& t : cj.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] = t.c;
      g = g.is_zero() ? rational_polynomial(c) : gcd(g, rational_polynomial(c));
      if (g.degree() == 0) return g;
    }
    return g;
  };
  const rational_polynomial c1 = content(e1);
  if (c1.degree() <= 0) return false;
  const rational_polynomial c2 = content(e2);
  return c2.degree() > 0 && gcd(c1, c2).degree() > 0;
}

// R with every factor of q that it holds more than once reduced to one copy: known multiple roots
// (the caller's spurious points) cost the square-free certificate otherwise.
rational_polynomial reduce_known_multiple_factors(rational_polynomial r, const rational_polynomial& q) {
  if (q.degree() < 1) return r;
  for (;;) {
    const rational_polynomial g = gcd(r, q);
    if (g.degree() < 1) return r;
    const rational_polynomial repeated = gcd(quotient(r, g), g);  // factors of q still in r after one copy
    if (repeated.degree() < 1) return r;
    r = quotient(r, repeated);
  }
}

}  // namespace

system_result solve_two_equations(const coefficient_polynomial& e1, const coefficient_polynomial& e2, int u, int v,
                                  int digits, solve_method method, const rational_polynomial& multiple_factor) {
  if (digits < 10) throw std::invalid_argument("at least 10 digits");
  system_result result;
  const auto start = clock_type::now();
  if (e1.is_zero() || e2.is_zero()) {
    result.degenerate = true;
    result.note = "a condition vanishes identically: the coefficients are not determined";
    return result;
  }
  const rational_polynomial ru = resultant_in(e1, e2, v, u);
  if (ru.is_zero() || share_factor_in_u(e1, e2, u, v)) {
    result.degenerate = true;
    result.note = "the two conditions share a factor: their solutions form a curve, not isolated points";
    return result;
  }
  result.resultant_degree_u = ru.degree();
  result.seconds_elimination = since(start);
  const auto roots_start = clock_type::now();
  const eliminant_roots in_u = isolate(reduce_known_multiple_factors(ru, multiple_factor));
  std::optional<std::vector<real_point>> points;
  std::vector<cln::cl_RA> multiple_roots;
  if (method == solve_method::automatic) points = back_substitute(e1, e2, u, v, in_u, digits, multiple_roots);
  if (!points) {  // the second resultant is timed with the pairing it serves
    result.paired = true;
    points = pair_roots(e1, e2, u, v, polished_roots(in_u, digits), digits);
  } else if (!multiple_roots.empty()) {
    result.multiple_roots = static_cast<int>(multiple_roots.size());
    // Above a multiple root there may be several solutions, or a singular one (a tangency), where
    // Newton in v from u0 alone loses half the digits: the v-resultant's certified roots decide.
    for (auto& p : pair_roots(e1, e2, u, v, multiple_roots, digits)) points->push_back(std::move(p));
  }
  result.points = std::move(*points);
  std::sort(result.points.begin(), result.points.end(),
            [](const real_point& a, const real_point& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
  result.seconds_roots = since(roots_start);
  return result;
}

}  // namespace rotlie::solver
