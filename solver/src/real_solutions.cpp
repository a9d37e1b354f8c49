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

#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

using lie::coefficient_polynomial;
using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }
cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

// A bivariate polynomial as rows c[i][j] of u^i v^j, evaluated exactly: first in u (once per root u),
// then in v by Horner.
class bivariate {
 public:
  bivariate(const coefficient_polynomial& p, int u, int v) {
    for (const auto& t : p.terms()) {
      const auto e = coefficient_polynomial::unpack(t.key);
      const auto i = static_cast<std::size_t>(e[static_cast<std::size_t>(u)]);
      const auto j = static_cast<std::size_t>(e[static_cast<std::size_t>(v)]);
      if (c_.size() <= i) c_.resize(i + 1);
      if (c_[i].size() <= j) c_[i].resize(j + 1, 0);
      c_[i][j] = t.c;
      degree_v_ = std::max(degree_v_, static_cast<int>(j));
    }
  }
  int degree_v() const { return degree_v_; }
  /// (value, magnitude) at u fixed, as polynomials in v: value Σ c_ij u^i v^j and Σ |c_ij| max(1,|u|)^i.
  struct in_v {
    std::vector<cln::cl_RA> value, magnitude;
  };
  in_v at_u(const cln::cl_RA& x) const {
    in_v r{std::vector<cln::cl_RA>(static_cast<std::size_t>(degree_v_) + 1, 0),
           std::vector<cln::cl_RA>(static_cast<std::size_t>(degree_v_) + 1, 0)};
    const cln::cl_RA ax = cln::max(cln::cl_RA(1), cln::abs(x));
    for (std::size_t i = c_.size(); i-- > 0;)
      for (std::size_t j = 0; j < r.value.size(); ++j) {
        const cln::cl_RA c = j < c_[i].size() ? c_[i][j] : cln::cl_RA(0);
        r.value[j] = r.value[j] * x + c;
        r.magnitude[j] = r.magnitude[j] * ax + cln::abs(c);
      }
    return r;
  }
  /// The degree in v at the root u* known to lie in (x − h, x + h): leading coefficients c_j(u) that
  /// change sign (or vanish) across that interval vanish at u* and are dropped.
  int degree_v_at_root(const cln::cl_RA& x, const cln::cl_RA& h) const {
    const auto coefficient_at = [&](int j, const cln::cl_RA& at) {
      cln::cl_RA s = 0;
      for (std::size_t i = c_.size(); i-- > 0;) s = s * at + (static_cast<std::size_t>(j) < c_[i].size() ? c_[i][static_cast<std::size_t>(j)] : cln::cl_RA(0));
      return s;
    };
    int d = degree_v_;
    while (d > 0 && cln::signum(coefficient_at(d, x - h)) * cln::signum(coefficient_at(d, x + h)) <= 0) --d;
    return d;
  }
  static cln::cl_RA horner(const std::vector<cln::cl_RA>& c, const cln::cl_RA& y) {
    cln::cl_RA s = 0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) s = s * y + *it;
    return s;
  }
  /// |e(x, y)| when it is below tolerance × (1 + size of the terms), i.e. (x, y) is a root to that width.
  std::optional<cln::cl_RA> vanishes(const in_v& at_x, const cln::cl_RA& y, const cln::cl_RA& tolerance) const {
    const cln::cl_RA ay = cln::max(cln::cl_RA(1), cln::abs(y));
    const cln::cl_RA r = cln::abs(horner(at_x.value, y));
    if (r <= tolerance * (1 + horner(at_x.magnitude, ay))) return r;
    return std::nullopt;
  }

 private:
  std::vector<std::vector<cln::cl_RA>> c_;
  int degree_v_ = 0;
};

// The same polynomial with floating-point coefficients of a fixed precision, for Newton's method.
class float_bivariate {
 public:
  float_bivariate(const coefficient_polynomial& p, int u, int v, const cln::float_format_t& format) {
    for (const auto& t : p.terms()) {
      const auto e = coefficient_polynomial::unpack(t.key);
      terms_.push_back({cln::cl_float(t.c, format), e[static_cast<std::size_t>(u)], e[static_cast<std::size_t>(v)]});
      degree_ = std::max({degree_, terms_.back().i, terms_.back().j});
    }
    zero_ = cln::cl_float(0, format);
  }
  cln::cl_F operator()(const std::vector<cln::cl_F>& pu, const std::vector<cln::cl_F>& pv) const {
    cln::cl_F s = zero_;
    for (const auto& t : terms_) s = s + t.c * pu[static_cast<std::size_t>(t.i)] * pv[static_cast<std::size_t>(t.j)];
    return s;
  }
  int degree() const { return degree_; }

 private:
  struct term {
    cln::cl_F c;
    int i, j;
  };
  std::vector<term> terms_;
  int degree_ = 0;
  cln::cl_F zero_;
};

std::vector<cln::cl_F> powers_of(const cln::cl_F& x, int degree) {
  std::vector<cln::cl_F> p{cln::cl_float(1, x)};
  for (int d = 1; d <= degree; ++d) p.push_back(p.back() * x);
  return p;
}

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
std::vector<std::complex<double>> complex_roots(const std::vector<cln::cl_RA>& exact) {
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

// Above a multiple root u0 of R (certified, exact) back-substitution's uniqueness fails: there may be
// several common roots, or a tangency. Every real root v of e1(u0, ·) and of e2(u0, ·) is polished by
// Newton's method in v on an equation where it is simple, and kept when both equations vanish.
std::vector<real_point> solve_above(const bivariate& b1, const bivariate& b2, const cln::cl_RA& u0, int digits) {
  const cln::float_format_t format = cln::float_format(digits + 30);
  const cln::cl_RA tolerance = ten_to_minus(digits + 3);
  const cln::cl_F converged = cln::cl_float(ten_to_minus(digits + 12), format);
  std::array<bivariate::in_v, 2> at{b1.at_u(u0), b2.at_u(u0)};
  // Coefficients that vanish at the exact root are zero, not tiny: else they add roots near infinity.
  const cln::cl_RA half_width = ten_to_minus(digits + 10) / 2;
  at[0].value.resize(static_cast<std::size_t>(b1.degree_v_at_root(u0, half_width)) + 1);
  at[1].value.resize(static_cast<std::size_t>(b2.degree_v_at_root(u0, half_width)) + 1);
  std::array<std::vector<cln::cl_F>, 2> value, slope;
  for (std::size_t e = 0; e < 2; ++e) {
    for (const auto& c : at[e].value) value[e].push_back(cln::cl_float(c, format));
    for (std::size_t j = 1; j < value[e].size(); ++j) slope[e].push_back(value[e][j] * cln::cl_float(cln::cl_I(static_cast<long>(j)), format));
  }
  const auto horner = [&](const std::vector<cln::cl_F>& c, const cln::cl_F& y) {
    cln::cl_F r = cln::cl_float(0, format);
    for (auto it = c.rbegin(); it != c.rend(); ++it) r = r * y + *it;
    return r;
  };
  std::vector<real_point> points;
  for (std::size_t source = 0; source < 2; ++source)
    for (const auto& z : complex_roots(at[source].value)) {
      if (std::abs(z.imag()) > 1e-4 * (1 + std::abs(z.real()))) continue;
      const cln::cl_F y0 = cln::cl_float(cln::rational(cln::cl_DF(z.real())), format);
      cln::cl_F y = y0;
      bool newton_converged = false;
      for (int iteration = 0; iteration < 60 && !newton_converged; ++iteration) {
        // Newton on the equation with the larger slope here: a tangency is a double root of one only.
        const cln::cl_F s0 = slope[0].empty() ? cln::cl_float(0, format) : horner(slope[0], y);
        const cln::cl_F s1 = slope[1].empty() ? cln::cl_float(0, format) : horner(slope[1], y);
        const std::size_t e = cln::abs(s0) >= cln::abs(s1) ? 0 : 1;
        const cln::cl_F s = e == 0 ? s0 : s1;
        if (cln::zerop(s)) break;
        const cln::cl_F step = horner(value[e], y) / s;
        y = y - step;
        newton_converged = cln::abs(step) <= converged * (1 + cln::abs(y));
      }
      // Polishing only: a start that runs away is not a root here (e.g. a point at infinity).
      if (!newton_converged || cln::abs(y - y0) > cln::cl_float(cln::cl_RA(1) / 10000, format) * (1 + cln::abs(y0))) continue;
      const cln::cl_RA yr = cln::rational(y);
      const auto r1 = b1.vanishes(at[0], yr, tolerance);
      if (!r1) continue;
      const auto r2 = b2.vanishes(at[1], yr, tolerance);
      if (!r2) continue;
      const bool seen = std::any_of(points.begin(), points.end(), [&](const real_point& p) {
        return cln::abs(p.v - yr) <= ten_to_minus(digits) * (1 + cln::abs(yr));
      });
      if (!seen) points.push_back({u0, yr, cln::max(*r1, *r2)});
    }
  return points;
}

// Back-substitution at every simple real root of the eliminant; nullopt when any root fails, so
// that the caller falls back to pairing.
// The multiple roots of R are set aside in `multiple_roots` for pairing.
std::optional<std::vector<real_point>> back_substitute(const coefficient_polynomial& e1, const coefficient_polynomial& e2,
                                                       int u, int v, const eliminant_roots& in_u, int digits,
                                                       std::vector<cln::cl_RA>& multiple_roots) {
  const cln::float_format_t format = cln::float_format(digits + 30);
  const float_bivariate f1(e1, u, v, format), f2(e2, u, v, format);
  const float_bivariate d1u(e1.derivative(u), u, v, format), d1v(e1.derivative(v), u, v, format);
  const float_bivariate d2u(e2.derivative(u), u, v, format), d2v(e2.derivative(v), u, v, format);
  const bivariate b1(e1, u, v), b2(e2, u, v);
  const int degree = std::max(f1.degree(), f2.degree());
  // The equation of lower positive degree in v gives the candidates; the other one selects.
  const bool first_is_lower = b2.degree_v() == 0 || (b1.degree_v() > 0 && b1.degree_v() <= b2.degree_v());
  const bivariate& low = first_is_lower ? b1 : b2;
  const bivariate& other = first_is_lower ? b2 : b1;
  const cln::cl_RA tolerance = ten_to_minus(digits + 3), width = ten_to_minus(digits + 10);
  const cln::cl_F converged = cln::cl_float(cln::cl_RA(width) / 100, format);
  std::vector<real_point> points;
  // Where both leading coefficients in v vanish, R vanishes for a point at infinity; R square-free
  // then leaves no finite solution above that root. Those roots are the roots of gcd(lc1, lc2).
  const auto leading = [&](const coefficient_polynomial& e) {
    const coefficient_polynomial lc = e.coefficient(v, e.degree(v));
    std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(lc.degree(u), 0)) + 1, 0);
    for (const auto& t : lc.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] = t.c;
    return rational_polynomial(std::move(c));
  };
  const rational_polynomial at_infinity = gcd(leading(e1), leading(e2));
  const root_polisher polisher(in_u.square_free, digits);
  for (const auto& interval : in_u.intervals) {
    const cln::cl_RA u0 = polisher.polish(interval);  // certified to width/2
    if (in_u.multiple.degree() >= 1 &&
        cln::signum(in_u.multiple(u0 - width / 2)) * cln::signum(in_u.multiple(u0 + width / 2)) <= 0) {
      multiple_roots.push_back(u0);
      continue;
    }
    if (at_infinity.degree() >= 1 && cln::signum(at_infinity(u0 - width / 2)) * cln::signum(at_infinity(u0 + width / 2)) <= 0)
      continue;
    const auto low_at = low.at_u(u0), other_at = other.at_u(u0);
    // Candidates: every root of low(u0, ·), ordered by how well the other equation vanishes.
    std::vector<std::pair<double, double>> candidates;  // (relative |other| + |imaginary part|, v)
    for (const auto& z : complex_roots(low_at.value)) {
      const double y = z.real();
      double value = 0, size = 0;
      for (std::size_t j = other_at.value.size(); j-- > 0;) {
        value = value * y + cln::double_approx(other_at.value[j]);
        size = size * std::max(1.0, std::abs(y)) + cln::double_approx(other_at.magnitude[j]);
      }
      candidates.push_back({std::abs(value) / (1 + size) + std::abs(z.imag()) / (1 + std::abs(y)), y});
    }
    std::sort(candidates.begin(), candidates.end());
    bool found = false;
    const cln::cl_F x0 = cln::cl_float(u0, format);
    for (std::size_t k = 0; k < std::min<std::size_t>(candidates.size(), 3) && !found; ++k) {
      // Newton on (e1, e2) in (u, v) from (u0, candidate): quadratic from about 16 digits. The
      // intersection is simple (R is square-free), so the Jacobian is regular there.
      const cln::cl_F y0 = cln::cl_float(cln::rational(cln::cl_DF(candidates[k].second)), format);
      cln::cl_F x = x0, y = y0;
      bool newton_converged = false;
      for (int iteration = 0; iteration < 40 && !newton_converged; ++iteration) {
        const auto pu = powers_of(x, degree), pv = powers_of(y, degree);
        const cln::cl_F a = d1u(pu, pv), b = d1v(pu, pv), c = d2u(pu, pv), d = d2v(pu, pv);
        const cln::cl_F det = a * d - b * c;
        if (cln::zerop(det)) break;
        const cln::cl_F r1 = f1(pu, pv), r2 = f2(pu, pv);
        const cln::cl_F dx = (d * r1 - b * r2) / det, dy = (a * r2 - c * r1) / det;
        x = x - dx;
        y = y - dy;
        newton_converged = cln::abs(dx) <= converged * (1 + cln::abs(x)) && cln::abs(dy) <= converged * (1 + cln::abs(y));
      }
      // Newton only polishes: it converged near its start (a root at infinity sends it away), on the
      // same root of R, and both equations vanish, exactly evaluated.
      if (!newton_converged || cln::abs(y - y0) > cln::cl_float(cln::cl_RA(1) / 1000000, format) * (1 + cln::abs(y0)) ||
          cln::abs(x - x0) > cln::cl_float(width, format))
        continue;
      const cln::cl_RA yr = cln::rational(y);
      const auto r1 = b1.vanishes(b1.at_u(u0), yr, tolerance);
      if (!r1) continue;
      const auto r2 = b2.vanishes(b2.at_u(u0), yr, tolerance);
      if (!r2) continue;
      points.push_back({u0, yr, cln::max(*r1, *r2)});
      found = true;
    }
    // No finite common root passed: a root at infinity (both leading coefficients in v vanish) or a
    // candidate Newton could not reach. Pairing decides those exactly.
    if (!found) return std::nullopt;
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
    const bivariate b1(e1, u, v), b2(e2, u, v);
    for (const auto& u0 : multiple_roots)
      for (auto& p : solve_above(b1, b2, u0, digits)) points->push_back(std::move(p));
  }
  result.points = std::move(*points);
  std::sort(result.points.begin(), result.points.end(),
            [](const real_point& a, const real_point& b) { return a.u != b.u ? a.u < b.u : a.v < b.v; });
  result.seconds_roots = since(roots_start);
  return result;
}

}  // namespace rotlie::solver
