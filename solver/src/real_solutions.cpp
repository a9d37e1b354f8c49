#include "rotlie/solver/real_solutions.hpp"

#include <algorithm>
#include <stdexcept>

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {
namespace {

// A bivariate polynomial as (coefficient, i, j) terms, for fast exact evaluation.
struct bivariate {
  struct term {
    cln::cl_RA c;
    int i, j;
  };
  std::vector<term> terms;
  cln::cl_RA scale = 0;  // Σ |c|

  bivariate(const GiNaC::ex& e, const GiNaC::symbol& u, const GiNaC::symbol& v) {
    const GiNaC::ex p = e.expand();
    for (int i = 0; i <= p.degree(u); ++i) {
      const GiNaC::ex pu = p.coeff(u, i);
      for (int j = 0; j <= pu.degree(v); ++j) {
        const GiNaC::ex c = pu.coeff(v, j);
        if (c.is_zero()) continue;
        if (!GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational())
          throw std::invalid_argument("the equations must have rational coefficients");
        const cln::cl_RA r = cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(c).to_cl_N());
        terms.push_back({r, i, j});
        scale = scale + cln::abs(r);
      }
    }
  }
  cln::cl_RA operator()(const cln::cl_RA& x, const cln::cl_RA& y) const {
    cln::cl_RA s = 0;
    for (const auto& t : terms) s = s + t.c * cln::expt(x, t.i) * cln::expt(y, t.j);
    return s;
  }
};

cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

std::vector<cln::cl_RA> real_roots(const GiNaC::ex& resultant, const GiNaC::symbol& x, const cln::cl_RA& width) {
  const auto p = rational_polynomial::from_ex(resultant, x).square_free();
  std::vector<cln::cl_RA> out;
  for (const auto& r : isolate_real_roots(p)) out.push_back(refine_root(p, r, width));
  return out;
}

}  // namespace

system_result solve_two_equations(const GiNaC::ex& e1, const GiNaC::ex& e2, const GiNaC::symbol& u,
                                  const GiNaC::symbol& v, int digits) {
  if (digits < 10) throw std::invalid_argument("at least 10 digits");
  system_result result;
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
  const GiNaC::ex ru = GiNaC::resultant(p1, p2, v).expand(), rv = GiNaC::resultant(p1, p2, u).expand();
  if (ru.is_zero() || rv.is_zero()) {
    result.degenerate = true;
    result.note = "the two conditions share a factor: their solutions form a curve, not isolated points";
    return result;
  }
  result.resultant_degree_u = ru.degree(u);
  result.resultant_degree_v = rv.degree(v);
  const cln::cl_RA width = ten_to_minus(digits + 10);
  const auto us = real_roots(ru, u, width), vs = real_roots(rv, v, width);
  const bivariate b1(p1, u, v), b2(p2, u, v);
  // True solutions evaluate to about |∇e|·width; anything else stays far above this threshold.
  const cln::cl_RA accept = ten_to_minus(digits + 3) * (1 + cln::max(b1.scale, b2.scale));
  for (const auto& x : us)
    for (const auto& y : vs) {
      const cln::cl_RA r = cln::max(cln::abs(b1(x, y)), cln::abs(b2(x, y)));
      if (r <= accept) result.points.push_back({x, y, r});
    }
  return result;
}

}  // namespace rotlie::solver
