#include "rotlie/solver/real_solutions.hpp"

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/real.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "bivariate_rows.hpp"
#include "roots_above.hpp"
#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

using namespace detail;
using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }

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

// Every real root of the eliminant, certified to 10^-(digits+10)/2.
std::vector<cln::cl_RA> polished_roots(const eliminant_roots& in_u, int digits) {
  const root_polisher polisher(in_u.square_free, digits);
  std::vector<cln::cl_RA> us;
  for (const auto& r : in_u.intervals) us.push_back(polisher.polish(r));
  return us;
}

// The pairing method: the real roots v of the other resultant, every pair with the given u tested.
std::vector<real_point> pair_roots(const coefficient_polynomial& e1, const coefficient_polynomial& e2, int u, int v,
                                   const std::vector<cln::cl_RA>& us, int digits) {
  const std::vector<cln::cl_RA> vs = polished_roots(isolate(resultant_in(e1, e2, u, v)), digits);
  const bivariate b1(e1, u, v), b2(e2, u, v);
  // A true solution leaves |e| ≲ deg·|terms|·width; any other pair leaves a fixed nonzero algebraic
  // number, far above 10^-(digits+3) of the size of the terms (relative: any multiple of e agrees).
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
  const rational_polynomial at_infinity = gcd(rows_in_u(e1, u, v).back(), rows_in_u(e2, u, v).back());
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
      if (auto found = common_roots_above_algebraic(e1, e2, u, v, in_u.square_free, in_u.multiple, interval, digits)) {
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
    for (const auto& row : rows_in_u(e, u, v)) {
      if (row.is_zero()) continue;
      g = g.is_zero() ? row : modular_gcd(g, row);
      if (g.degree() == 0) break;
    }
    return g;
  };
  const rational_polynomial c1 = content(e1);
  if (c1.degree() <= 0) return false;
  const rational_polynomial c2 = content(e2);
  return c2.degree() > 0 && modular_gcd(c1, c2).degree() > 0;
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

int count_real_eliminant_roots(const coefficient_polynomial& given1, const coefficient_polynomial& given2, int u, int v,
                               const rational_polynomial& multiple_factor) {
  const coefficient_polynomial e1 = given1.primitive_integer(), e2 = given2.primitive_integer();
  if (e1.is_zero() || e2.is_zero()) return -1;
  const rational_polynomial ru = resultant_in(e1, e2, v, u);
  if (ru.is_zero() || share_factor_in_u(e1, e2, u, v)) return -1;
  return static_cast<int>(isolate(reduce_known_multiple_factors(ru, multiple_factor)).intervals.size());
}

system_result solve_two_equations(const coefficient_polynomial& given1, const coefficient_polynomial& given2, int u, int v,
                                  int digits, solve_method method, const rational_polynomial& multiple_factor) {
  if (digits < 10) throw std::invalid_argument("at least 10 digits");
  // Coprime integer coefficients (a positive multiple of each): the same zero set, the same
  // polynomials for any positive multiple of the input (a body in any unit), and integer arithmetic.
  const coefficient_polynomial e1 = given1.primitive_integer(), e2 = given2.primitive_integer();
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
  result.real_roots_u = static_cast<int>(in_u.intervals.size());
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
