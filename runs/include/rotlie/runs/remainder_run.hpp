#pragma once
// `remainder` for every front end: the request as typed, checked once (the word, its size against
// the order, the coefficient values), then the modified Hamiltonian computed (bch/remainder_request).
// The limits on a raw word's size live here so that the CLI and Python refuse the same inputs.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rotlie/bch/remainder_request.hpp"

namespace rotlie::runs {

/// A coefficient given a value: its name (a1, b2, …) and the number as typed (1/6, 0.25).
using coefficient_text = std::pair<std::string, std::string>;

struct remainder_inputs {
  std::string scheme;        ///< a paper's name (N2, P7, RSRSRSR) or a word (ABCBA)
  std::string split;         ///< "", ABC or RS ("" = from the word's letters)
  std::string perm = "ABC";  ///< the permutation assigning A, B, C to G1², G2², G3²
  std::string order = "5";   ///< the highest order K, 1 … bch::max_remainder_order
  std::string inertia;       ///< a body name or I1,I2,I3; empty = symbolic moments
  std::vector<coefficient_text> coefficients;
};

/// "a1=1/6,b1=0.25" (the CLI's --coeffs) as name/text pairs; "" gives none. Throws bad_input for
/// an item that is not name=value or a name that is not a coefficient's.
std::vector<coefficient_text> coefficient_list(std::string_view text);

/// Checks the request as the CLI does (throws bad_input naming the option) and computes it.
bch::remainder_result remainder_run(const remainder_inputs& in);

}  // namespace rotlie::runs
