#include "rotlie/lie/theorems.hpp"

#include <algorithm>

namespace rotlie::lie {

bool theorem1_allows(int order, const monomial& m) {
  if (order < 1 || m.degree() != degree_of_order(order)) return false;
  if (order == 1) return m[0] == 2 || m[1] == 2 || m[2] == 2;
  const bool even_order = order % 2 == 0;
  for (int i = 0; i < 3; ++i) {
    if (even_order != (m[i] % 2 == 1)) return false;  // eq. 23: odd exponents; eq. 24: even ones
    if (!even_order && m[i] / 2 > static_cast<std::uint32_t>((order - 1) / 2)) return false;  // p, q, r ≤ k
  }
  return true;
}

std::vector<monomial> theorem1_monomials(int order) {
  std::vector<monomial> out;
  const std::uint32_t d = degree_of_order(order);
  for (std::uint32_t e1 = 0; e1 <= d; ++e1)
    for (std::uint32_t e2 = 0; e1 + e2 <= d; ++e2)
      if (monomial m(e1, e2, d - e1 - e2); theorem1_allows(order, m)) out.push_back(m);
  std::sort(out.begin(), out.end());
  return out;
}

cln::cl_I theorem2_weight(const monomial& m) {
  cln::cl_I w = 1;
  for (int i = 0; i < 3; ++i)
    if (m[i] >= 2) w = w * cln::doublefactorial(m[i] - 1);  // (2p)!/(2^p p!) = (2p−1)!!
  return w;
}

cln::cl_RA theorem2_pairing(const polynomial<cln::cl_RA>& x) {
  cln::cl_RA s = 0;
  for (const auto& [m, c] : x.terms()) s = s + theorem2_weight(m) * c;
  return s;
}

std::size_t theorem_bound(int order) {
  return theorem1_monomials(order).size() - (theorem2_applies(order) ? 1 : 0);
}

std::vector<polynomial<cln::cl_RA>> theorem_space_basis(int order) {
  const auto mons = theorem1_monomials(order);
  std::vector<polynomial<cln::cl_RA>> basis;
  if (!theorem2_applies(order)) {
    for (const auto& m : mons) basis.push_back(polynomial<cln::cl_RA>::term(m, 1));
    return basis;
  }
  // One relation (eq. 28): pair every other monomial with the first one, λ0·m − λm·m0.
  const monomial& m0 = mons.front();
  const cln::cl_I w0 = theorem2_weight(m0);
  for (std::size_t i = 1; i < mons.size(); ++i) {
    const cln::cl_I wi = theorem2_weight(mons[i]);
    const cln::cl_I g = cln::gcd(w0, wi);
    auto v = polynomial<cln::cl_RA>::term(mons[i], cln::exquo(w0, g));
    v.add_term(m0, -cln::exquo(wi, g));
    basis.push_back(std::move(v));
  }
  return basis;
}

}  // namespace rotlie::lie
