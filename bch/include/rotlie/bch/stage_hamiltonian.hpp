#pragma once
// The modified Hamiltonian of a long scheme word, symbolic in its free stage coefficients, for a body
// with rational moments: H_R1 … H_R9 with coefficients in lie::multivariate_polynomial (up to 16
// unknowns), computed by the nested BCH expansion directly in the Lie–Poisson algebra (no free-algebra
// step, no GiNaC). compute_exact_modified_hamiltonian does the same for at most 4 unknowns.
#include <cln/rational.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/multivariate_polynomial.hpp"
#include "rotlie/lie/polynomial.hpp"

namespace rotlie::bch {

using stage_polynomial = lie::polynomial<lie::multivariate_polynomial>;

struct stage_hamiltonian {
  int max_order = 0;
  std::vector<std::string> unknowns;         ///< names of x_0, x_1, … (layout.free_coefficients)
  std::vector<stage_polynomial> remainder;   ///< remainder[k] = H_Rk, k = 1 … max_order
  std::map<std::string, lie::multivariate_polynomial> coefficient_values;  ///< every stage coefficient's name → its value
};

/// w = (1/I1, 1/I2, 1/I3), any positive rationals. Throws std::invalid_argument for an order outside
/// 1 … max_remainder_order or more than 16 free coefficients.
stage_hamiltonian compute_stage_hamiltonian(const scheme_layout& layout, const std::array<cln::cl_RA, 3>& w, int max_order);

}  // namespace rotlie::bch
