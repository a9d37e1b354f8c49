#pragma once
// Critical points of f on the curve g1 = g2 = 0 in three unknowns (section 3.4: minimise ‖H_R5‖²
// with H_R3 = 0). By Lagrange, ∇f, ∇g1, ∇g2 are dependent there, so the points solve
// g1 = g2 = det[∇f; ∇g1; ∇g2] = 0. One condition is linear in some unknown z = −B/A; substituting
// it leaves two equations in two unknowns for solve_two_equations, and every point found is
// checked back in all three equations.
#include <cln/rational.h>

#include "rotlie/lie/coefficient_polynomial.hpp"
#include "rotlie/solver/real_solutions.hpp"

#include <array>
#include <string>
#include <vector>

namespace rotlie::solver {

struct critical_point {
  std::array<cln::cl_RA, 3> values;  ///< x_0, x_1, x_2, within 10^-(digits+10)
  cln::cl_RA residual;               ///< max |g1|, |g2|, |det| relative to the size of their terms
};

struct critical_result {
  bool degenerate = false;
  std::string note;                   ///< why degenerate, or what was discarded
  std::vector<critical_point> points;  ///< sorted by the first unknown
  int eliminated = -1;                 ///< the unknown solved linearly
  int eliminant_degree = 0;            ///< degree of the univariate resultant in the first remaining unknown
  int eliminant_real_roots = -1;       ///< its distinct real roots (count_critical_candidates); −1 degenerate
  int discarded = 0;                   ///< roots of the reduced system where the linear solve fails (A = 0)
  double seconds_elimination = 0;      ///< Lagrange determinant, substitution, resultants
  double seconds_roots = 0;            ///< isolation, refinement, pairing and the check in three unknowns
};

/// All real critical points of f restricted to g1 = g2 = 0, polynomials in the unknowns x_0, x_1, x_2
/// with rational coefficients, to `digits` digits.
/// method: how the reduced planar system is solved (automatic, or pairing as the second method).
critical_result constrained_critical_points(const lie::coefficient_polynomial& f, const lie::coefficient_polynomial& g1,
                                            const lie::coefficient_polynomial& g2, int digits,
                                            solve_method method = solve_method::automatic);

/// The number of distinct real roots of the eliminant constrained_critical_points isolates (−1 when
/// it reports the system degenerate), at about half its cost: where it stays the same between two
/// bodies and every solution carries over, no real solution was born or died between them.
int count_critical_candidates(const lie::coefficient_polynomial& f, const lie::coefficient_polynomial& g1,
                              const lie::coefficient_polynomial& g2);

/// The planar system of constrained_critical_points before it is solved: g1, g2 and the Lagrange
/// determinant with integer coefficients, the unknown x_eliminated = −B/A solved from the linear
/// condition, and the two equations left in x_rest[0], x_rest[1] (common factors with A removed).
struct reduced_lagrange_system {
  bool degenerate = true;
  std::string note;  ///< why degenerate
  lie::coefficient_polynomial g1, g2, det, A, B, reduced_other, reduced_det;
  int eliminated = -1;
  std::array<int, 2> rest{};
};
reduced_lagrange_system reduce_lagrange_system(const lie::coefficient_polynomial& f, const lie::coefficient_polynomial& g1,
                                               const lie::coefficient_polynomial& g2);

}  // namespace rotlie::solver
