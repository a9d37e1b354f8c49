#pragma once
// The nested BCH expansion of a scheme in the Lie–Poisson algebra, for any coefficient ring R
// (GiNaC expressions, exact rationals, polynomials in the stage coefficients, doubles): the stages
// x_i = c_i X_i are combined by the symmetric BCH series from the middle outwards for a palindrome
// (log(e^x e^Z e^x)), by the BCH series from the left otherwise. Order k ↔ polynomial degree k + 1.
#include <cln/rational.h>
#include <cln/real.h>
#include <ginac/ginac.h>

#include <map>
#include <type_traits>
#include <vector>

#include "rotlie/bch/evaluate.hpp"
#include "rotlie/bch/lie_series.hpp"
#include "rotlie/lie/multivariate_polynomial.hpp"
#include "rotlie/lie/poisson_bracket.hpp"
#include "rotlie/lie/stop_request.hpp"

namespace rotlie::bch {

/// The BCH (symmetric = false) or symmetric BCH series to degree max_order, computed once per
/// process and shared (thread-safe).
const lie_series& cached_bch_series(int max_order, bool symmetric);

/// The Lie–Poisson algebra truncated at a maximal order: terms of order > max_order
/// (polynomial degree > max_order + 1) are dropped as soon as they appear.
template <class R>
struct truncated_poisson_algebra {
  int max_order;
  lie::polynomial<R> bracket(const lie::polynomial<R>& a, const lie::polynomial<R>& b) const {
    lie::polynomial<R> out;
    const auto max_degree = static_cast<std::uint32_t>(max_order + 1);
    for (const auto& [ma, ca] : a.terms())
      for (const auto& [mb, cb] : b.terms()) {
        if (ma.degree() + mb.degree() - 1 > max_degree) continue;  // {deg p, deg q} has degree p + q − 1
        bool any = false;  // {G^a, G^b} = 0 (e.g. both monomials even powers of one G_i): skip the product
        lie::bracket_of_monomials(ma, mb, [&](const lie::monomial&, long) { any = true; });
        if (!any) continue;
        const R product = ca * cb;
        if constexpr (std::is_same_v<R, lie::multivariate_polynomial>)  // in place: no copy of the product per output
          lie::bracket_of_monomials(ma, mb, [&](const lie::monomial& m, long c) { out.add_term_multiple(m, product, c); });
        else
          lie::bracket_of_monomials(ma, mb, [&](const lie::monomial& m, long c) { out.add_term(m, R(c) * product); });
      }
    return out;
  }
  void add_scaled(lie::polynomial<R>& acc, const cln::cl_RA& c, const lie::polynomial<R>& x) const {
    const R factor = scalar(c);
    for (const auto& [m, v] : x.terms()) acc.add_term(m, factor * v);
  }
  static R scalar(const cln::cl_RA& c) {
    if constexpr (std::is_same_v<R, GiNaC::ex>)
      return GiNaC::numeric(cln::cl_N(c));
    else if constexpr (std::is_same_v<R, double>)
      return cln::double_approx(c);
    else
      return R(c);
  }
  lie::polynomial<R> zero() const { return {}; }
};

/// H_R0 … H_R(max_order) of the stage list x (by_order[k] = the terms of polynomial degree k + 1).
template <class R>
std::vector<lie::polynomial<R>> nested_bch(const std::vector<lie::polynomial<R>>& x, bool palindrome, int max_order) {
  const truncated_poisson_algebra<R> algebra{max_order};
  lie::polynomial<R> z;
  if (palindrome) {
    const auto& series = cached_bch_series(max_order, true);
    const std::size_t n = x.size();
    z = x[n / 2];
    for (std::size_t i = n / 2; i-- > 0;) {
      lie::stop_point();
      z = evaluate(series, std::vector<lie::polynomial<R>>{x[i], z}, algebra, max_order);
    }
  } else {
    const auto& series = cached_bch_series(max_order, false);
    z = x.front();
    for (std::size_t i = 1; i < x.size(); ++i) {
      lie::stop_point();
      z = evaluate(series, std::vector<lie::polynomial<R>>{z, x[i]}, algebra, max_order);
    }
  }
  std::vector<lie::polynomial<R>> by_order(static_cast<std::size_t>(max_order) + 1);
  for (const auto& [m, c] : z.terms()) by_order[m.degree() - 1].add_term(m, c);
  return by_order;
}

}  // namespace rotlie::bch
