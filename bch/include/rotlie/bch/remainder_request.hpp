#pragma once
// What `rotlie remainder` asks: a scheme (paper name or raw word), splitting, permutation,
// order, optional body and optional values of free coefficients — validated, then computed.
#include <cln/rational.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::bch {

struct remainder_request {
  std::string scheme;                                          ///< N1…N7, R, P1…P15, RSRSRSR, SRSRSRS, or a word
  std::optional<splitting> split;                              ///< required to agree with a named scheme
  std::string permutation = "ABC";
  int order = 5;
  std::optional<lie::moments_of_inertia> inertia;              ///< symbolic I1, I2, I3 when absent
  std::vector<std::pair<std::string, cln::cl_RA>> coefficients;  ///< values of free coefficients
};

struct remainder_result {
  std::string name;                   ///< the paper's name, or empty for a raw word
  scheme_layout layout;
  modified_hamiltonian k;
  std::vector<std::string> free;      ///< free coefficients left symbolic
  std::vector<GiNaC::symbol> symbols; ///< every symbol in the coefficients, in printing order
};

/// Longest word that compute_remainder expands to `order` (1 … max_remainder_order), so that every
/// accepted request ends within about a minute instead of running for hours: the symbolic
/// expansion grows steeply with both. Palindromes (symmetric BCH) cost far less than other words
/// (BCH nested from the left). Measured worst case (symbolic body, one process, 2-core machine):
///   palindromes   order 5: 25 stages 3.8 s, 33 stages 36 s
///                 order 7: 13 stages 11 s, 17 stages 38 s, 21 stages > 120 s
///                 order 9:  9 stages 41 s, 11 stages 58 s, 13 stages > 300 s
///   other words   order 3: 25 stages 1.7 s
///                 order 5: 13 stages 2.2 s, 17 stages 33 s, 25 stages > 120 s
///                 order 7:  7 stages 46 s,  9 stages 160 s
///                 order 9:  5 stages 55 s,  6 stages 70 s, 9 stages > 300 s
/// Every scheme of the paper (at most 11 stages, palindromes) fits up to order 9.
constexpr std::size_t max_remainder_stages(int order, bool symmetric) {
  if (symmetric) return order <= 5 ? max_word_length : order <= 7 ? 17 : 11;
  return order <= 3 ? max_word_length : order <= 5 ? 13 : order <= 7 ? 7 : 5;
}

/// Throws std::invalid_argument with a one-line reason for anything malformed, and for a word
/// longer than max_remainder_stages at the order asked.
remainder_result compute_remainder(const remainder_request& request);

}  // namespace rotlie::bch
