#include "rotlie/solver/critical_points.hpp"

#include <cln/float.h>
#include <cln/real.h>
#include <ginac/ginac.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "bivariate_rows.hpp"
#include "rotlie/solver/real_solutions.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

using lie::coefficient_polynomial;
using detail::ten_to_minus;

coefficient_polynomial determinant3(const coefficient_polynomial& f, const coefficient_polynomial& g1,
                                    const coefficient_polynomial& g2) {
  std::array<std::array<coefficient_polynomial, 3>, 3> m;
  for (int j = 0; j < 3; ++j) {
    m[0][static_cast<std::size_t>(j)] = f.derivative(j);
    m[1][static_cast<std::size_t>(j)] = g1.derivative(j);
    m[2][static_cast<std::size_t>(j)] = g2.derivative(j);
  }
  // Along the first row: f's gradient is the largest polynomial, so it is multiplied once per term.
  const auto minor = [&](int a, int b) { return m[1][static_cast<std::size_t>(a)] * m[2][static_cast<std::size_t>(b)] -
                                                m[1][static_cast<std::size_t>(b)] * m[2][static_cast<std::size_t>(a)]; };
  return m[0][0] * minor(1, 2) - m[0][1] * minor(0, 2) + m[0][2] * minor(0, 1);
}

// p(z = −B/A) · A^deg_z(p): a polynomial in the remaining unknowns, by Horner in −B,
// L_d = p_d, L_k = L_{k+1}·(−B) + p_k·A^(d−k), so that only the small −B multiplies the growing sum.
coefficient_polynomial substitute_linear(const coefficient_polynomial& p, int z, const coefficient_polynomial& A,
                                         const coefficient_polynomial& B) {
  const int d = p.degree(z);
  const coefficient_polynomial minus_b = -B;
  coefficient_polynomial a_power(1), out = p.coefficient(z, d);
  for (int k = d - 1; k >= 0; --k) {
    a_power = a_power * A;
    out = out * minus_b + p.coefficient(z, k) * a_power;
  }
  return out;
}

// GiNaC for the multivariate gcd only, which is rare here (the linear coefficient A is usually constant).
GiNaC::ex to_ex(const coefficient_polynomial& p, const std::array<GiNaC::symbol, 3>& s) {
  GiNaC::ex out = 0;
  for (const auto& t : p.terms()) {
    const auto e = coefficient_polynomial::unpack(t.key);
    GiNaC::ex term = GiNaC::numeric(cln::cl_N(t.c));
    for (std::size_t k = 0; k < 3; ++k) term *= GiNaC::pow(s[k], e[k]);
    out += term;
  }
  return out;
}
coefficient_polynomial from_ex(const GiNaC::ex& e, const std::array<GiNaC::symbol, 3>& s) {
  coefficient_polynomial out;
  const GiNaC::ex p = e.expand();
  for (int i = 0; i <= p.degree(s[0]); ++i) {
    const GiNaC::ex pi = p.coeff(s[0], i);
    for (int j = 0; j <= pi.degree(s[1]); ++j) {
      const GiNaC::ex pj = pi.coeff(s[1], j);
      for (int k = 0; k <= pj.degree(s[2]); ++k) {
        const GiNaC::ex c = pj.coeff(s[2], k);
        if (!c.is_zero())
          out += coefficient_polynomial::monomial({i, j, k, 0}, cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(c).to_cl_N()));
      }
    }
  }
  return out;
}
const std::array<GiNaC::symbol, 3>& gcd_symbols() {
  static const std::array<GiNaC::symbol, 3> s{GiNaC::symbol("x0"), GiNaC::symbol("x1"), GiNaC::symbol("x2")};
  return s;
}
bool nonconstant_gcd(const coefficient_polynomial& a, const coefficient_polynomial& b) {
  if (a.is_constant() || b.is_constant()) return false;
  const GiNaC::ex g = GiNaC::gcd(to_ex(a, gcd_symbols()), to_ex(b, gcd_symbols()));
  return !GiNaC::is_a<GiNaC::numeric>(g);
}

// Removes from p every factor it shares with A: those vanish where z = −B/A is undefined.
coefficient_polynomial strip_common_factors(const coefficient_polynomial& p, const coefficient_polynomial& A) {
  if (A.is_constant()) return p;
  // A is small (degree 2 here): its irreducible factors by GiNaC, then exact division of the large
  // p by each while it divides, on the packed terms (GiNaC's division of p took most of the solve).
  const auto& s = gcd_symbols();
  const GiNaC::ex factored = GiNaC::factor(to_ex(A, s));
  GiNaC::exvector factors;
  if (GiNaC::is_a<GiNaC::mul>(factored))
    for (std::size_t i = 0; i < factored.nops(); ++i) factors.push_back(factored.op(i));
  else
    factors.push_back(factored);
  coefficient_polynomial out = p;
  for (GiNaC::ex f : factors) {
    if (GiNaC::is_a<GiNaC::power>(f)) f = f.op(0);
    if (GiNaC::is_a<GiNaC::numeric>(f)) continue;
    const coefficient_polynomial factor = from_ex(f, s);
    for (coefficient_polynomial quotient; lie::divide_exactly(out, factor, quotient);) out = std::move(quotient);
  }
  return out;
}

// |p(x)| / Σ |terms| in floating point of digits + 30 digits: vanishes to the refinement width at a
// true root, O(1) elsewhere; the rounding error is 10^-27 of the threshold. Relative to the terms
// alone (never to 1), so any multiple of p gives the same verdict.
class relative_value {
 public:
  relative_value(const coefficient_polynomial& p, const cln::float_format_t& format) : format_(format) {
    for (const auto& t : p.terms()) terms_.push_back({cln::cl_float(t.c, format), coefficient_polynomial::unpack(t.key)});
    for (const auto& t : terms_) degree_ = std::max({degree_, t.e[0], t.e[1], t.e[2]});
  }
  cln::cl_F operator()(const std::array<cln::cl_RA, 3>& x) const {
    std::array<std::vector<cln::cl_F>, 3> powers;
    for (std::size_t v = 0; v < 3; ++v) {
      const cln::cl_F xv = cln::cl_float(x[v], format_);
      powers[v].push_back(cln::cl_float(1, format_));
      for (int d = 1; d <= degree_; ++d) powers[v].push_back(powers[v].back() * xv);
    }
    cln::cl_F value = cln::cl_float(0, format_), size = cln::cl_float(0, format_);
    for (const auto& t : terms_) {
      const cln::cl_F product = t.c * powers[0][static_cast<std::size_t>(t.e[0])] * powers[1][static_cast<std::size_t>(t.e[1])] *
                                powers[2][static_cast<std::size_t>(t.e[2])];
      value = value + product;
      size = size + cln::abs(product);
    }
    return cln::zerop(size) ? size : cln::abs(value) / size;
  }

 private:
  struct term {
    cln::cl_F c;
    coefficient_polynomial::exponents e;
  };
  cln::float_format_t format_;
  std::vector<term> terms_;
  int degree_ = 0;
};

}  // namespace

reduced_lagrange_system reduce_lagrange_system(const coefficient_polynomial& f, const coefficient_polynomial& g1,
                                               const coefficient_polynomial& g2) {
  reduced_lagrange_system r;
  r.g1 = g1.primitive_integer();
  r.g2 = g2.primitive_integer();
  const coefficient_polynomial &e1 = r.g1, &e2 = r.g2;
  // Integer coefficients throughout (same zero sets): rational arithmetic would pay a gcd per operation.
  r.det = determinant3(f.primitive_integer(), e1, e2).primitive_integer();
  const coefficient_polynomial& det = r.det;
  if (e1.is_zero() || e2.is_zero() || det.is_zero()) {
    r.note = "a condition or the Lagrange determinant vanishes identically";
    return r;
  }
  // The linear unknown with the simplest leading coefficient A (a constant avoids any spurious root).
  int best_eq = -1, best_var = -1, best_cost = 1 << 30;
  const std::array<const coefficient_polynomial*, 2> eqs{&e1, &e2};
  for (int q = 0; q < 2; ++q)
    for (int v = 0; v < 3; ++v) {
      if (eqs[static_cast<std::size_t>(q)]->degree(v) != 1) continue;
      const int cost = eqs[static_cast<std::size_t>(q)]->coefficient(v, 1).total_degree();
      if (cost < best_cost) best_eq = q, best_var = v, best_cost = cost;
    }
  if (best_eq < 0) {
    r.note = "no order condition is linear in an unknown: this elimination does not apply";
    return r;
  }
  const int z = best_var;
  const coefficient_polynomial& linear = *eqs[static_cast<std::size_t>(best_eq)];
  const coefficient_polynomial& other = *eqs[static_cast<std::size_t>(1 - best_eq)];
  r.A = linear.coefficient(z, 1);
  r.B = linear.coefficient(z, 0);
  if (nonconstant_gcd(r.A, r.B)) {
    r.note = "the linear condition factors: its zero set contains a whole surface";
    return r;
  }
  for (int v = 0, k = 0; v < 3; ++v)
    if (v != z) r.rest[static_cast<std::size_t>(k++)] = v;
  r.eliminated = z;
  r.reduced_other = strip_common_factors(substitute_linear(other, z, r.A, r.B), r.A).primitive_integer();
  r.reduced_det = strip_common_factors(substitute_linear(det, z, r.A, r.B), r.A).primitive_integer();
  r.degenerate = false;
  return r;
}

namespace {

// Where A = B = 0 both reduced equations vanish to high order: those points are multiple roots of
// the eliminant, at the roots of Res(A, B) (none for a constant A).
rational_polynomial spurious_factor(const reduced_lagrange_system& r) {
  return r.A.is_constant() ? rational_polynomial() : resultant_in(r.A, r.B, r.rest[1], r.rest[0]);
}

}  // namespace

int count_critical_candidates(const coefficient_polynomial& f, const coefficient_polynomial& g1,
                              const coefficient_polynomial& g2) {
  const reduced_lagrange_system reduced = reduce_lagrange_system(f, g1, g2);
  if (reduced.degenerate) return -1;
  return count_real_eliminant_roots(reduced.reduced_other, reduced.reduced_det, reduced.rest[0], reduced.rest[1],
                                    spurious_factor(reduced));
}

critical_result constrained_critical_points(const coefficient_polynomial& f, const coefficient_polynomial& g1,
                                            const coefficient_polynomial& g2, int digits, solve_method method) {
  critical_result result;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const reduced_lagrange_system reduced = reduce_lagrange_system(f, g1, g2);
  if (reduced.degenerate) {
    result.degenerate = true;
    result.note = reduced.note;
    return result;
  }
  const coefficient_polynomial &e1 = reduced.g1, &e2 = reduced.g2, &det = reduced.det, &A = reduced.A, &B = reduced.B;
  const int z = reduced.eliminated;
  const std::array<int, 2> rest = reduced.rest;
  result.eliminated = z;
  const coefficient_polynomial &reduced_other = reduced.reduced_other, &reduced_det = reduced.reduced_det;
  // The spurious multiple roots (A = B = 0) are kept once (then discarded below), not certified away.
  const rational_polynomial spurious = spurious_factor(reduced);
  const system_result planar = solve_two_equations(reduced_other, reduced_det, rest[0], rest[1], digits,
                                                   method, spurious);
  result.eliminant_degree = planar.resultant_degree_u;
  if (!planar.degenerate) result.eliminant_real_roots = planar.real_roots_u;
  const auto check_start = clock::now();
  result.seconds_elimination = std::chrono::duration<double>(check_start - start).count() - planar.seconds_roots;
  result.seconds_roots = planar.seconds_roots;
  if (planar.degenerate) {
    result.degenerate = true;
    result.note = planar.note;
    return result;
  }
  const cln::cl_RA tolerance = ten_to_minus(digits + 2);
  const cln::float_format_t format = cln::float_format(digits + 30);
  const relative_value check1(e1, format), check2(e2, format), check_det(det, format), check_a(A, format);
  const cln::cl_F float_tolerance = cln::cl_float(tolerance, format);
  for (const auto& p : planar.points) {
    std::vector<cln::cl_RA> at(3, 0);
    at[static_cast<std::size_t>(rest[0])] = p.u;
    at[static_cast<std::size_t>(rest[1])] = p.v;
    const cln::cl_RA a = A(at), b = B(at);
    // A vanishes there relative to its terms: z = −B/A is undefined (a constant A never does).
    if (cln::zerop(a) || check_a({at[0], at[1], at[2]}) <= float_tolerance) {
      ++result.discarded;
      continue;
    }
    critical_point c;
    c.values = {at[0], at[1], at[2]};
    c.values[static_cast<std::size_t>(z)] = -b / a;
    const cln::cl_F worst = cln::max(check1(c.values), cln::max(check2(c.values), check_det(c.values)));
    if (worst > float_tolerance) {
      ++result.discarded;
      continue;
    }
    c.residual = cln::rational(worst);
    result.points.push_back(std::move(c));
  }
  if (result.discarded > 0)
    result.note = std::to_string(result.discarded) + " root(s) of the reduced system discarded: the linear solve for x_" +
                  std::to_string(z) + " is undefined there";
  // By the first unknown, ties (several solutions above one root, on flat bodies) by the next: the
  // labels must not depend on the order the roots were found in.
  std::sort(result.points.begin(), result.points.end(),
            [](const critical_point& x, const critical_point& y) { return x.values < y.values; });
  result.seconds_roots += std::chrono::duration<double>(clock::now() - check_start).count();
  return result;
}

}  // namespace rotlie::solver
