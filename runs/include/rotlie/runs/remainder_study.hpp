#pragma once
// The computation behind the report's section "Remainder formulas": the paper's third-order remainders
// in its variables (x, y), the resultants behind eqs. (60)-(61) and (78)-(84), and the structure of
// H_R5 for every named scheme (eqs. 62-63). Plain results (GiNaC expressions where the result is a
// formula); reports/remainder_section prints them in LaTeX and markdown.
#include <ginac/ginac.h>

#include <array>
#include <string>
#include <vector>

namespace rotlie::runs {

/// P'_1, P'_2, P'_3 of a scheme: the coefficients of G1²G2², G1²G3², G2²G3² in H_R3, scaled by 2I1 = 1.
struct remainder_third_order {
  std::string scheme;
  std::vector<GiNaC::symbol> symbols;  ///< free coefficients, then x, y
  std::array<GiNaC::ex, 3> P;
};

/// Res_v2(P'_1, P'_2) of a scheme, expanded.
struct remainder_elimination {
  std::string scheme;
  GiNaC::symbol v2;  ///< the eliminated free coefficient
  std::vector<GiNaC::symbol> symbols;
  GiNaC::ex resultant;
};

/// H_R5 of a named scheme, symbolic in the moments: its size and Theorems 1-2 checked.
struct remainder_structure {
  std::string name, word;
  std::size_t terms = 0;
  bool support = true;   ///< every monomial on Theorem 1's support (eq. 62)
  bool reduction = true;  ///< 3(Q1+…+Q6) + Q7 = 0 (eq. 63)
};

struct remainder_study_result {
  std::vector<remainder_third_order> third_order;  ///< RSRSRSR, SRSRSRS, N4
  std::vector<remainder_elimination> eliminations;  ///< N1 … N7 (N4 only with `quick`)
  std::vector<remainder_structure> structure;       ///< every named scheme (N4, P1, R with `quick`)
  double seconds = 0;                               ///< wall time
};

remainder_study_result remainder_study(bool quick);

}  // namespace rotlie::runs
