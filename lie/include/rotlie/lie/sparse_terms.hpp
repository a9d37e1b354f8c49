#pragma once
// The two loops every packed-key sparse polynomial needs (coefficient_polynomial,
// multivariate_polynomial): terms are {key, coefficient} kept sorted by an integer key with no zero
// coefficient. The coefficient's type, its name and how two are added stay with each polynomial;
// the callables below are inlined, so the loops cost what the hand-written ones did.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace rotlie::lie {

/// The sorted merge of two term lists sorted by key. A key on one side only gives from_a(term of a)
/// (a's terms may be moved from) or from_b(term of b); a key on both gives sum(term of a, term of b),
/// kept unless is_zero says the coefficients cancelled.
template <class Term, class FromA, class FromB, class Sum, class IsZero>
std::vector<Term> merge_sorted_terms(std::vector<Term>& a, const std::vector<Term>& b, FromA from_a, FromB from_b, Sum sum,
                                     IsZero is_zero) {
  std::vector<Term> merged;
  merged.reserve(a.size() + b.size());
  auto x = a.begin();
  auto y = b.cbegin();
  while (x != a.end() || y != b.cend()) {
    if (y == b.cend() || (x != a.end() && x->key < y->key)) {
      merged.push_back(from_a(*x++));
    } else if (x == a.end() || y->key < x->key) {
      merged.push_back(from_b(*y++));
    } else {
      Term t = sum(*x, *y);
      if (!is_zero(t)) merged.push_back(std::move(t));
      ++x, ++y;
    }
  }
  return merged;
}

/// Sorts terms in any order by key, in place: equal keys added (add(into, from)), the terms that
/// cancel (is_zero) dropped.
template <class Term, class Add, class IsZero>
void sort_and_combine_terms(std::vector<Term>& v, Add add, IsZero is_zero) {
  std::sort(v.begin(), v.end(), [](const Term& a, const Term& b) { return a.key < b.key; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i + 1;
    if (out != i) v[out] = v[i];
    for (; j < v.size() && v[j].key == v[out].key; ++j) add(v[out], v[j]);
    if (!is_zero(v[out])) ++out;
    i = j;
  }
  v.resize(out);
}

}  // namespace rotlie::lie
