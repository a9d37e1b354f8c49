#include "rotlie/bch/lie_series.hpp"

#include <stdexcept>

#include "rotlie/bch/free_bch.hpp"

namespace rotlie::bch {

std::size_t lie_series::nonzero_at_degree(int d) const {
  std::size_t n = 0;
  for (const auto& [w, c] : coefficients) n += static_cast<int>(w.size()) == d;
  return n;
}

namespace {

// P_w in a series truncated at max_degree ≥ |w| (products of truncated series keep the smaller
// truncation, so every factor is built at the full degree).
word_series bracket_expansion(const word& w, int max_degree) {
  word_series p(max_degree);
  if (w.size() == 1) {
    p.add(w, 1);
    return p;
  }
  const auto [u, v] = standard_factorization(w);
  const word_series pu = bracket_expansion(u, max_degree), pv = bracket_expansion(v, max_degree);
  word_series vu = pv * pu;
  vu *= cln::cl_RA(-1);
  p = pu * pv;
  p += vu;
  return p;
}

}  // namespace

word_series lyndon_bracket_expansion(const word& w) { return bracket_expansion(w, static_cast<int>(w.size())); }

lie_series lyndon_coordinates(const word_series& z, int letters) {
  lie_series s;
  s.letters = letters;
  s.max_degree = z.max_degree();
  if (!z.degree(0).empty()) throw std::logic_error("a Lie element has no constant term");
  for (int d = 1; d <= z.max_degree(); ++d) {
    // Residual of degree d; Lyndon words in increasing lexicographic order read off their
    // coefficient, because P_w = w + (lexicographically larger words).
    std::map<word, cln::cl_RA> residual = z.degree(d);
    for (const auto& w : lyndon_words(letters, d)) {
      if (static_cast<int>(w.size()) != d) continue;
      const auto it = residual.find(w);
      if (it == residual.end()) continue;
      const cln::cl_RA c = it->second;
      s.coefficients.emplace(w, c);
      const word_series expansion = lyndon_bracket_expansion(w);
      for (const auto& [x, cx] : expansion.degree(d)) {
        auto [r, inserted] = residual.try_emplace(x, 0);
        r->second = r->second - c * cx;
        if (cln::zerop(r->second)) residual.erase(r);
      }
    }
    if (!residual.empty()) throw std::logic_error("the series is not a Lie element at degree " + std::to_string(d));
  }
  return s;
}

lie_series bch_series(int max_degree) { return to_lie_series(compute_free_series(free_series::xy, max_degree)); }

lie_series symmetric_bch_series(int max_degree) { return to_lie_series(compute_free_series(free_series::xyx, max_degree)); }

lie_series bch_series_by_words(int max_degree) {
  if (max_degree < 1) throw std::invalid_argument("the BCH degree must be at least 1");
  const auto product = word_series::exp_of_letter(0, max_degree) * word_series::exp_of_letter(1, max_degree);
  return lyndon_coordinates(log(product), 2);
}

lie_series symmetric_bch_series_by_words(int max_degree) {
  if (max_degree < 1) throw std::invalid_argument("the BCH degree must be at least 1");
  const auto ex = word_series::exp_of_letter(0, max_degree);
  const auto product = ex * word_series::exp_of_letter(1, max_degree) * ex;
  return lyndon_coordinates(log(product), 2);
}

}  // namespace rotlie::bch
