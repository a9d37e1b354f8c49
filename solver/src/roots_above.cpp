#include "roots_above.hpp"

#include <cln/integer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "rotlie/solver/residue_field.hpp"

namespace rotlie::solver::detail {

// The common root above a simple root u0 of the eliminant (certified to width/2), which is unique
// and real. Starting points: every root of either equation at u0 (companion matrices, double
// precision), best first by how well the other equation vanishes there. Each is polished by Newton's
// method in v on the equation with the larger slope, then by Newton's method on (e1, e2) in (u, v),
// whose Jacobian is regular at a simple intersection: v at u0 alone would carry u0's error times
// dv/du. Kept when u stays within width/2 of u0 and both equations vanish to 10^-(digits+3) of
// the size of their terms (never of 1: the verdict is the same for any multiple of an equation), all
// in floating point of digits + 30 digits.
std::optional<real_point> common_root_above(const float_system& f, const cln::cl_RA& u0, int digits) {
  const cln::float_format_t format = cln::float_format(digits + 30);
  const cln::cl_F tolerance = cln::cl_float(ten_to_minus(digits + 3), format);
  const cln::cl_F converged = cln::cl_float(ten_to_minus(digits + 12), format);
  const cln::cl_F one = cln::cl_float(1, format);
  const cln::cl_F x0 = cln::cl_float(u0, format);
  const cln::cl_F half_width = cln::cl_float(ten_to_minus(digits + 10) / 2, format);
  std::array<float_bivariate_rows::in_v, 2> at{f.e1.at_u(x0), f.e2.at_u(x0)};
  // Coefficients that vanish at the exact root are zero, not tiny: else they add roots near infinity.
  at[0].value.resize(static_cast<std::size_t>(f.e1.degree_v_at_root(x0, half_width)) + 1);
  at[1].value.resize(static_cast<std::size_t>(f.e2.degree_v_at_root(x0, half_width)) + 1);
  const std::array<std::vector<cln::cl_F>, 2> slope{derivative(at[0].value), derivative(at[1].value)};
  std::vector<std::pair<double, double>> starts;  // (relative |other| + |imaginary part|, v)
  for (std::size_t source = 0; source < 2; ++source) {
    const auto& other = at[1 - source];
    for (const auto& z : complex_roots(at[source].value)) {
      const double y = z.real();
      if (!std::isfinite(y) || !std::isfinite(z.imag())) continue;  // a root at infinity in double
      // In the precision of the rows: a double would overflow for equations far from unit size.
      const cln::cl_F yf = cln::cl_float(cln::rational(cln::cl_DF(y)), format);
      const cln::cl_F value = horner(other.value, yf), size = horner(other.magnitude, cln::max(one, cln::abs(yf)));
      const double relative = cln::zerop(size) ? 0.0 : cln::double_approx(cln::abs(value) / size);
      starts.push_back({relative + std::abs(z.imag()) / (1 + std::abs(y)), y});
    }
  }
  std::sort(starts.begin(), starts.end());
  for (const auto& [score, start] : starts) {
    if (score > 1e-3) break;  // far from a common root: the remaining starts are worse
    const cln::cl_F y0 = cln::cl_float(cln::rational(cln::cl_DF(start)), format);
    cln::cl_F y = y0;
    bool newton_converged = false;
    for (int iteration = 0; iteration < 60 && !newton_converged; ++iteration) {
      const cln::cl_F s0 = horner(slope[0], y), s1 = horner(slope[1], y);
      // Slopes relative to each equation's own size: one may be a large multiple of a small factor.
      const cln::cl_F ay = cln::max(one, cln::abs(y));
      const cln::cl_F size0 = horner(at[0].magnitude, ay), size1 = horner(at[1].magnitude, ay);
      const std::size_t e = cln::abs(s0) * size1 >= cln::abs(s1) * size0 ? 0 : 1;  // |s0|/size0 ≥ |s1|/size1
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
  const auto at = [&](const coefficient_polynomial& e) {  // e(r, ·): the rows in v of e with u = r
    std::vector<cln::cl_RA> c;
    for (const auto& row : rows_in_u(e, u, v)) c.push_back(row(r));
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
                                                                    const rational_polynomial& square_free,
                                                                    const rational_polynomial& multiple,
                                                                    const root_interval& interval, int digits) {
  const root_polisher fine(square_free, digits + 20);
  const cln::cl_RA alpha = fine.polish(interval);  // within 10^-(digits+30)/2
  const cln::cl_RA half_width = ten_to_minus(digits + 30) / 2;
  residue_field field(multiple, alpha - half_width, alpha + half_width);
  const auto coefficients_in_v = [&](const coefficient_polynomial& e) {
    std::vector<rational_polynomial> rows = rows_in_u(e, u, v);
    for (auto& row : rows) row = field.reduce(row);
    return rows;
  };
  std::vector<real_point> points;
  auto g = field.gcd_in_v(coefficients_in_v(e1), coefficients_in_v(e2));
  if (g.size() <= 1) return points;  // coprime above α: no common root
  std::vector<rational_polynomial> g_slope;  // ∂g/∂v in Q(α)[v]
  for (std::size_t j = 1; j < g.size(); ++j) g_slope.push_back(g[j] * rational_polynomial({cln::cl_RA(static_cast<long>(j))}));
  const auto repeated = field.gcd_in_v(g, g_slope);
  if (repeated.size() > 1) g = field.quotient_in_v(g, repeated);
  // g's coefficients at α, in floating point; its real roots are simple now.
  const cln::float_format_t format = cln::float_format(digits + 30);
  const cln::cl_F a = cln::cl_float(alpha, format), one = cln::cl_float(1, format);
  std::vector<cln::cl_F> value;
  for (const auto& c : g) {
    std::vector<cln::cl_F> coefficients;
    for (const auto& x : c.coefficients()) coefficients.push_back(cln::cl_float(x, format));
    value.push_back(horner(coefficients, a));
  }
  const std::vector<cln::cl_F> slope = derivative(value);
  const cln::cl_F converged = cln::cl_float(ten_to_minus(digits + 15), format);
  const cln::cl_F tolerance = cln::cl_float(ten_to_minus(digits + 3), format);
  const float_bivariate_rows b1(e1, u, v, format), b2(e2, u, v, format);
  const auto at1 = b1.at_u(a), at2 = b2.at_u(a);
  for (const auto& z : complex_roots(value)) {
    if (!std::isfinite(z.real()) || !std::isfinite(z.imag())) return std::nullopt;  // not concluded: pair instead
    if (std::abs(z.imag()) > 1e-6 * (1 + std::abs(z.real()))) continue;  // a conjugate pair
    cln::cl_F y = cln::cl_float(cln::rational(cln::cl_DF(z.real())), format);
    bool newton_converged = false;
    for (int iteration = 0; iteration < 60 && !newton_converged; ++iteration) {
      const cln::cl_F s = horner(slope, y);
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

}  // namespace rotlie::solver::detail
