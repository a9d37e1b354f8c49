#include "rotlie/solver/real_solutions.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

cln::cl_RA rational_of(const GiNaC::ex& c) {
  if (!GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational())
    throw std::invalid_argument("the equations must have rational coefficients");
  return cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(c).to_cl_N());
}

// A bivariate polynomial as rows c[i][j] of u^i v^j, evaluated exactly: first in u (once per root u),
// then in v by Horner, so pairing n × m roots costs n·terms + n·m·deg_v operations.
class bivariate {
 public:
  bivariate(const GiNaC::ex& e, const GiNaC::symbol& u, const GiNaC::symbol& v) {
    const GiNaC::ex p = e.expand();
    c_.resize(static_cast<std::size_t>(p.degree(u)) + 1);
    for (int i = 0; i <= p.degree(u); ++i) {
      const GiNaC::ex pu = p.coeff(u, i);
      for (int j = 0; j <= pu.degree(v); ++j) {
        auto& row = c_[static_cast<std::size_t>(i)];
        row.resize(static_cast<std::size_t>(pu.degree(v)) + 1, 0);
        row[static_cast<std::size_t>(j)] = rational_of(pu.coeff(v, j));
      }
    }
    for (const auto& row : c_) degree_v_ = std::max(degree_v_, static_cast<int>(row.size()) - 1);
  }
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
  static cln::cl_RA horner(const std::vector<cln::cl_RA>& c, const cln::cl_RA& y) {
    cln::cl_RA s = 0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) s = s * y + *it;
    return s;
  }

 private:
  std::vector<std::vector<cln::cl_RA>> c_;
  int degree_v_ = 0;
};

cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

// The real roots of a univariate resultant, refined by exact bisection to `width`. The square-free
// part comes from GiNaC's gcd (heuristic integer gcd), far faster than Euclid over Q at high degree.
std::vector<cln::cl_RA> real_roots(const rational_polynomial& eliminant, const cln::cl_RA& width) {
  std::vector<cln::cl_RA> out;
  if (square_free_certified_mod_prime(eliminant)) {  // the usual case: skip the gcd over Q
    for (const auto& r : isolate_real_roots_of_square_free(eliminant)) out.push_back(refine_root(eliminant, r, width));
    return out;
  }
  const GiNaC::symbol x("x");
  GiNaC::ex resultant = 0;
  for (std::size_t i = 0; i < eliminant.coefficients().size(); ++i)
    resultant += GiNaC::numeric(cln::cl_N(eliminant.coefficients()[i])) * GiNaC::pow(x, static_cast<int>(i));
  const GiNaC::ex g = GiNaC::gcd(resultant, resultant.diff(x));
  const GiNaC::ex square_free = GiNaC::quo(resultant, g, x);
  const auto p = rational_polynomial::from_ex(square_free, x);
  for (const auto& r : isolate_real_roots_of_square_free(p)) out.push_back(refine_root(p, r, width));
  return out;
}

}  // namespace

system_result solve_two_equations(const GiNaC::ex& e1, const GiNaC::ex& e2, const GiNaC::symbol& u,
                                  const GiNaC::symbol& v, int digits) {
  if (digits < 10) throw std::invalid_argument("at least 10 digits");
  system_result result;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const GiNaC::ex p1 = e1.expand(), p2 = e2.expand();
  if (p1.is_zero() || p2.is_zero()) {
    result.degenerate = true;
    result.note = "a condition vanishes identically: the coefficients are not determined";
    return result;
  }
  if (const GiNaC::ex g = GiNaC::gcd(p1, p2); g.degree(u) > 0 || g.degree(v) > 0) {
    result.degenerate = true;
    result.note = "the two conditions share a factor: their solutions form a curve, not isolated points";
    return result;
  }
  const rational_polynomial ru = resultant_in(p1, p2, v, u), rv = resultant_in(p1, p2, u, v);
  if (ru.is_zero() || rv.is_zero()) {
    result.degenerate = true;
    result.note = "the two conditions share a factor: their solutions form a curve, not isolated points";
    return result;
  }
  const auto eliminated = clock::now();
  result.seconds_elimination = std::chrono::duration<double>(eliminated - start).count();
  result.resultant_degree_u = ru.degree();
  result.resultant_degree_v = rv.degree();
  const cln::cl_RA width = ten_to_minus(digits + 10);
  const auto us = real_roots(ru, width), vs = real_roots(rv, width);
  const bivariate b1(p1, u, v), b2(p2, u, v);
  // A true solution leaves |e| ≲ deg·|terms|·width; any other pair leaves a fixed nonzero algebraic
  // number, far above 10^-(digits+3) of the size of the terms.
  const cln::cl_RA tolerance = ten_to_minus(digits + 3);
  for (const auto& x : us) {
    const auto f1 = b1.at_u(x), f2 = b2.at_u(x);
    for (const auto& y : vs) {
      const cln::cl_RA ay = cln::max(cln::cl_RA(1), cln::abs(y));
      const cln::cl_RA r1 = cln::abs(bivariate::horner(f1.value, y)), r2 = cln::abs(bivariate::horner(f2.value, y));
      if (r1 <= tolerance * (1 + bivariate::horner(f1.magnitude, ay)) &&
          r2 <= tolerance * (1 + bivariate::horner(f2.magnitude, ay)))
        result.points.push_back({x, y, cln::max(r1, r2)});
    }
  }
  result.seconds_roots = std::chrono::duration<double>(clock::now() - eliminated).count();
  return result;
}

}  // namespace rotlie::solver
