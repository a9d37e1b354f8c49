#include "rotlie/solver/critical_points.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "rotlie/solver/real_solutions.hpp"

namespace rotlie::solver {
namespace {

GiNaC::ex exact(const cln::cl_RA& x) { return GiNaC::numeric(cln::cl_N(x)); }
cln::cl_RA rational(const GiNaC::ex& e) { return cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(e).to_cl_N()); }
cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

GiNaC::ex determinant3(const GiNaC::ex& f, const GiNaC::ex& g1, const GiNaC::ex& g2, const std::array<GiNaC::symbol, 3>& s) {
  GiNaC::matrix m(3, 3);
  for (unsigned j = 0; j < 3; ++j) {
    m(0, j) = f.diff(s[j]);
    m(1, j) = g1.diff(s[j]);
    m(2, j) = g2.diff(s[j]);
  }
  return m.determinant().expand();
}

// p(z = −B/A) · A^deg_z(p): a polynomial in the remaining unknowns.
GiNaC::ex substitute_linear(const GiNaC::ex& p, const GiNaC::symbol& z, const GiNaC::ex& A, const GiNaC::ex& B) {
  const int d = p.degree(z);
  GiNaC::ex out = 0;
  for (int k = 0; k <= d; ++k) out += p.coeff(z, k) * GiNaC::pow(-B, k) * GiNaC::pow(A, d - k);
  return out.expand();
}

// Removes from p every factor it shares with A: those vanish where z = −B/A is undefined.
GiNaC::ex strip_common_factors(GiNaC::ex p, const GiNaC::ex& A, const std::array<GiNaC::symbol, 3>& s) {
  for (;;) {
    const GiNaC::ex g = GiNaC::gcd(p, A);
    if (g.degree(s[0]) + g.degree(s[1]) + g.degree(s[2]) == 0) return p;
    GiNaC::ex quotient;
    if (!GiNaC::divide(p, g, quotient)) throw std::logic_error("a gcd does not divide its argument");
    p = quotient.expand();
  }
}

// A polynomial in the three unknowns as (coefficient, exponents) terms, for exact evaluation
// without GiNaC: the check in three unknowns runs once per root and the determinant has
// hundreds of terms.
class sparse3 {
 public:
  sparse3(const GiNaC::ex& p, const std::array<GiNaC::symbol, 3>& s) {
    const GiNaC::ex e = p.expand();
    for (int i = 0; i <= e.degree(s[0]); ++i) {
      const GiNaC::ex ei = e.coeff(s[0], i);
      for (int j = 0; j <= ei.degree(s[1]); ++j) {
        const GiNaC::ex ej = ei.coeff(s[1], j);
        for (int k = 0; k <= ej.degree(s[2]); ++k) {
          const GiNaC::ex c = ej.coeff(s[2], k);
          if (!c.is_zero()) terms_.push_back({rational(c), {i, j, k}});
          degree_ = std::max({degree_, i, j, k});
        }
      }
    }
  }
  /// |p(x)| / (1 + Σ |terms|): vanishes to the refinement width at a true root, O(1) elsewhere.
  cln::cl_RA relative_value(const std::array<cln::cl_RA, 3>& x) const {
    std::array<std::vector<cln::cl_RA>, 3> powers;
    for (std::size_t v = 0; v < 3; ++v) {
      powers[v].push_back(1);
      for (int d = 1; d <= degree_; ++d) powers[v].push_back(powers[v].back() * x[v]);
    }
    cln::cl_RA value = 0, size = 1;
    for (const auto& t : terms_) {
      const cln::cl_RA product = t.c * powers[0][static_cast<std::size_t>(t.e[0])] * powers[1][static_cast<std::size_t>(t.e[1])] *
                              powers[2][static_cast<std::size_t>(t.e[2])];
      value = value + product;
      size = size + cln::abs(product);
    }
    return cln::abs(value) / size;
  }

 private:
  struct term {
    cln::cl_RA c;
    std::array<int, 3> e;
  };
  std::vector<term> terms_;
  int degree_ = 0;
};

}  // namespace

critical_result constrained_critical_points(const GiNaC::ex& f, const GiNaC::ex& g1, const GiNaC::ex& g2,
                                            const std::array<GiNaC::symbol, 3>& s, int digits) {
  critical_result result;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const GiNaC::ex e1 = g1.expand(), e2 = g2.expand();
  const GiNaC::ex det = determinant3(f.expand(), e1, e2, s);
  if (e1.is_zero() || e2.is_zero() || det.is_zero()) {
    result.degenerate = true;
    result.note = "a condition or the Lagrange determinant vanishes identically";
    return result;
  }
  // The linear unknown with the simplest leading coefficient A (a constant avoids any spurious root).
  int best_eq = -1, best_var = -1, best_cost = 1 << 30;
  const std::array<GiNaC::ex, 2> eqs{e1, e2};
  for (int q = 0; q < 2; ++q)
    for (int v = 0; v < 3; ++v) {
      if (eqs[q].degree(s[v]) != 1) continue;
      const GiNaC::ex A = eqs[q].coeff(s[v], 1);
      const int cost = A.degree(s[0]) + A.degree(s[1]) + A.degree(s[2]);
      if (cost < best_cost) best_eq = q, best_var = v, best_cost = cost;
    }
  if (best_eq < 0) {
    result.degenerate = true;
    result.note = "no order condition is linear in an unknown: this elimination does not apply";
    return result;
  }
  const GiNaC::symbol z = s[best_var];
  const GiNaC::ex linear = eqs[best_eq], other = eqs[1 - best_eq];
  const GiNaC::ex A = linear.coeff(z, 1), B = linear.coeff(z, 0);
  if (const GiNaC::ex h = GiNaC::gcd(A, B); h.degree(s[0]) + h.degree(s[1]) + h.degree(s[2]) > 0) {
    result.degenerate = true;
    result.note = "the linear condition factors: its zero set contains a whole surface";
    return result;
  }
  std::array<GiNaC::symbol, 2> rest;
  for (int v = 0, k = 0; v < 3; ++v)
    if (v != best_var) rest[k++] = s[v];
  result.eliminated = z.get_name();
  const GiNaC::ex reduced_other = strip_common_factors(substitute_linear(other, z, A, B), A, s);
  const GiNaC::ex reduced_det = strip_common_factors(substitute_linear(det, z, A, B), A, s);
  const system_result planar = solve_two_equations(reduced_other, reduced_det, rest[0], rest[1], digits);
  result.eliminant_degree = planar.resultant_degree_u;
  const auto check_start = clock::now();
  result.seconds_elimination = std::chrono::duration<double>(check_start - start).count() - planar.seconds_roots;
  result.seconds_roots = planar.seconds_roots;
  if (planar.degenerate) {
    result.degenerate = true;
    result.note = planar.note;
    return result;
  }
  const cln::cl_RA tolerance = ten_to_minus(digits + 2);
  const sparse3 check1(e1, s), check2(e2, s), check_det(det, s);
  for (const auto& p : planar.points) {
    const GiNaC::exmap at2{{rest[0], exact(p.u)}, {rest[1], exact(p.v)}};
    const cln::cl_RA a = rational(A.subs(at2)), b = rational(B.subs(at2));
    if (cln::abs(a) <= tolerance * (1 + cln::abs(b))) {
      ++result.discarded;
      continue;
    }
    critical_point c;
    c.values[static_cast<std::size_t>(best_var)] = -b / a;
    for (int v = 0, k = 0; v < 3; ++v)
      if (v != best_var) c.values[static_cast<std::size_t>(v)] = k++ == 0 ? p.u : p.v;
    c.residual = cln::max(check1.relative_value(c.values),
                          cln::max(check2.relative_value(c.values), check_det.relative_value(c.values)));
    if (c.residual > tolerance) {
      ++result.discarded;
      continue;
    }
    result.points.push_back(std::move(c));
  }
  if (result.discarded > 0)
    result.note = std::to_string(result.discarded) + " root(s) of the reduced system discarded: the linear solve for " +
                  result.eliminated + " is undefined there";
  std::sort(result.points.begin(), result.points.end(),
            [](const critical_point& x, const critical_point& y) { return x.values[0] < y.values[0]; });
  result.seconds_roots += std::chrono::duration<double>(clock::now() - check_start).count();
  return result;
}

}  // namespace rotlie::solver
