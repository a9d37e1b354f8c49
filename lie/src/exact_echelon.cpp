#include "rotlie/lie/exact_echelon.hpp"

namespace rotlie::lie {

polynomial<cln::cl_RA> exact_echelon::reduce(polynomial<cln::cl_RA> v) const {
  // Eliminate pivot monomials from the top down; each step removes the current pivot term
  // and only introduces smaller monomials, so the loop ends.
  auto it = v.terms().rbegin();
  while (it != v.terms().rend()) {
    const auto pivot = pivots_.find(it->first);
    if (pivot == pivots_.end()) {
      ++it;
      continue;
    }
    const monomial m = it->first;
    v -= pivot->second * it->second;
    it = std::make_reverse_iterator(v.terms().lower_bound(m));
  }
  return v;
}

bool exact_echelon::add(const polynomial<cln::cl_RA>& v) {
  auto r = reduce(v);
  if (r.is_zero()) return false;
  const monomial lead = r.leading_monomial();
  r *= cln::recip(r.coefficient(lead));
  pivots_.emplace(lead, std::move(r));
  return true;
}

bool exact_echelon::contains(const polynomial<cln::cl_RA>& v) const { return reduce(v).is_zero(); }

std::vector<polynomial<cln::cl_RA>> exact_echelon::basis() const {
  std::vector<polynomial<cln::cl_RA>> out;
  for (const auto& [m, row] : pivots_) out.push_back(row);
  return out;
}

}  // namespace rotlie::lie
