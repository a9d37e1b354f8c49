#pragma once
// Evaluation of a Lie series in any Lie algebra: the same series serves on matrices
// (commutators, the numeric check) and on lie/'s Lie–Poisson polynomials.
#include <map>
#include <vector>

#include "rotlie/bch/lie_series.hpp"

namespace rotlie::bch {

/// Algebra is any type with
///   Element bracket(const Element&, const Element&) const;
///   void add_scaled(Element& acc, const cln::cl_RA& c, const Element& x) const;   // acc += c x
///   Element zero() const;
/// Words longer than max_length are skipped (grading: a word of length n contributes only at
/// order ≥ n when every letter has order ≥ 1).
template <class Algebra, class Element>
Element evaluate(const lie_series& s, const std::vector<Element>& letters, const Algebra& algebra,
                 int max_length = 1 << 30) {
  std::map<word, Element> memo;  // P_w for the Lyndon words met so far
  auto value = [&](auto&& self, const word& w) -> const Element& {
    if (auto it = memo.find(w); it != memo.end()) return it->second;
    Element v = w.size() == 1 ? letters.at(w[0]) : [&] {
      const auto [u, x] = standard_factorization(w);
      return algebra.bracket(self(self, u), self(self, x));
    }();
    return memo.emplace(w, std::move(v)).first->second;
  };
  Element sum = algebra.zero();
  for (const auto& [w, c] : s.coefficients)
    if (static_cast<int>(w.size()) <= max_length) algebra.add_scaled(sum, c, value(value, w));
  return sum;
}

}  // namespace rotlie::bch
