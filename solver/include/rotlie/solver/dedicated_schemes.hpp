#pragma once
// Dedicated 4th-order schemes for one body (section 3): the conditions H_R3 = 0 (two independent
// equations after Theorem 2: the coefficients P1 of G1²G2² and P2 of G1²G3²). With two free stage
// coefficients (N1–N7, RSRSRSR, SRSRSRS) all their real solutions; with three (R, P1–P15, section
// 3.4) all real critical points of ‖H_R5‖² on that curve. Labelled by ascending first free
// coefficient, with residual and analytic remainder ‖H_R5‖ (eq. 64).
#include <cln/rational.h>

#include <string>
#include <utility>
#include <vector>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::solver {

struct dedicated_solution {
  std::string scheme;        ///< N1 … N7, RSRSRSR, …
  std::string permutation;   ///< ABC … BAC
  int label = 0;             ///< 1, 2, … by ascending first free coefficient
  bch::scheme_layout layout;
  /// Every coefficient name (a1, b1, a2, …) → exact rational within 10^-(digits+10) of the solution.
  std::vector<std::pair<std::string, cln::cl_RA>> coefficients;
  std::vector<std::string> free;  ///< names of the free coefficients
  std::vector<std::string> exact;  ///< coefficients fixed to an exact rational by the first-order conditions alone
  /// max over the conditions up to order 4 of |value| / Σ|terms| at the coefficients as a table of
  /// `digits` digits writes them (certify_order_four): relative, so the same in any unit
  cln::cl_RA residual;
  double analytic_remainder = 0;  ///< ‖H_R5‖ (eq. 64), natural units, body scaled to I3 = 1
  std::string name() const { return scheme + " " + permutation + " (" + std::to_string(label) + ")"; }
};

struct system_report {
  std::string scheme, permutation;
  int real_solutions = 0;
  bool degenerate = false;
  std::string note;
  int eliminant_degree = 0;  ///< degree of the univariate resultant whose real roots were isolated
  int eliminant_real_roots = -1;  ///< R, P: its distinct real roots (count_critical_candidates); −1 degenerate
  std::string eliminated;    ///< R, P: the coefficient solved linearly from one condition
  int discarded = 0;         ///< R, P: roots of the reduced system where that linear solve is undefined
  int uncertified = 0;       ///< roots dropped because their written coefficients do not certify order 4
};

struct family_result {
  std::vector<dedicated_solution> solutions;  ///< sorted by analytic remainder
  std::vector<system_report> systems;
  double seconds_conditions = 0, seconds_elimination = 0, seconds_roots = 0, seconds_remainder = 0;
};

/// Solves every (scheme, permutation) pair; schemes must have two or three free coefficients. The
/// body may be given in any unit: the result is that of the body scaled to I3 = 1.
/// Throws std::invalid_argument for an unknown scheme or permutation or digits < 10.
family_result solve_dedicated(const lie::moments_of_inertia& body, const std::vector<std::string>& schemes,
                              const std::vector<std::string>& permutations, int digits);

/// The order conditions of an exact expansion: P1, P2 (the coefficients of G1²G2² and G1²G3² in
/// H_R3), and ‖H_R5‖² = Σ q² over H_R5's coefficients when the expansion reaches order 5 (else 0).
struct order_conditions {
  lie::coefficient_polynomial p1, p2, norm_squared;
};
order_conditions conditions_of(const bch::exact_modified_hamiltonian& k);

/// ‖H_R5‖ from its coefficients q for the body scaled to I3 = 1: the normalisation that reproduces
/// Tables 3 and 4 (see the implementation).
double analytic_remainder_norm(const std::vector<double>& q);

/// (I1/I3, I2/I3, 1), exactly: the body every solution is computed for.
lie::moments_of_inertia scaled_to_unit_I3(const lie::moments_of_inertia& body);

}  // namespace rotlie::solver
