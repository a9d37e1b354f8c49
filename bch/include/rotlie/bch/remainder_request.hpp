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

/// Throws std::invalid_argument with a one-line reason for anything malformed.
remainder_result compute_remainder(const remainder_request& request);

}  // namespace rotlie::bch
