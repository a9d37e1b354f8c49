#pragma once
// Lie series in the Lyndon basis with exact rational coefficients: the BCH series
// log(e^X e^Y) and the symmetric BCH series log(e^X e^Y e^X), to any degree, computed as
// the logarithm in the free associative algebra projected onto the Lyndon basis (no
// hand-typed formula).
#include <cln/rational.h>

#include <map>
#include <vector>

#include "rotlie/bch/word.hpp"
#include "rotlie/bch/word_series.hpp"

namespace rotlie::bch {

/// Orders Lyndon words by length, then lexicographically.
struct by_length_then_lex {
  bool operator()(const word& a, const word& b) const { return a.size() != b.size() ? a.size() < b.size() : a < b; }
};

struct lie_series {
  int letters = 2;
  int max_degree = 0;
  std::map<word, cln::cl_RA, by_length_then_lex> coefficients;  ///< Lyndon word → coefficient (nonzero only)

  std::size_t nonzero_at_degree(int d) const;
};

/// P_w expanded in the free associative algebra (w Lyndon): P_a = a, P_uv = P_u P_v − P_v P_u.
word_series lyndon_bracket_expansion(const word& w);

/// Coordinates of a Lie element of the free associative algebra in the Lyndon basis.
/// Uses triangularity (P_w = w + larger words of the same length); throws std::logic_error
/// if z is not a Lie element (the residual does not vanish), which checks the computation.
lie_series lyndon_coordinates(const word_series& z, int letters);

/// Highest degree of bch_series and symmetric_bch_series (free_bch.hpp: max_series_degree).
inline constexpr int max_bch_degree = 20;

/// log(e^X e^Y) with X = letter 0 (A), Y = letter 1 (B), degrees 1 … max_degree (free_bch.hpp).
lie_series bch_series(int max_degree);

/// log(e^X e^Y e^X), which has only odd degrees (free_bch.hpp).
lie_series symmetric_bch_series(int max_degree);

/// The same two series by the logarithm in the free associative algebra projected with
/// lyndon_coordinates: slow (degree ≤ 12 or so), kept as an independent second method.
lie_series bch_series_by_words(int max_degree);
lie_series symmetric_bch_series_by_words(int max_degree);

}  // namespace rotlie::bch
