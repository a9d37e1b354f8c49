#pragma once
// "Solve a body" in one call: every real solution of the dedicated schemes of a one-parameter family
// (N, R, P) for a body, ranked by ‖H_R5‖ (eq. 64), as `rotlie solve` and rotlie.solve() run it.
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

/// What to solve, as the user types it: family N, R or P; one member ("N2") or "" for all; a
/// permutation or "all"/""; the body ("water", "1/2,4/5,1"); the coefficients' significant digits.
struct solve_request {
  std::string family, scheme, perm, body;
  int digits = 40;
};

struct solved_body {
  lie::moments_of_inertia body;
  solver::family_result result;         ///< the solutions ranked, and one report per system
  std::vector<std::string> warnings;    ///< a system undefined for this body (others were asked), uncertified roots
};

/// The largest --digits (beyond it the exact bisection dominates for no use).
inline constexpr int max_solve_digits = 300;

/// Solves the request. Throws bad_input for bad names, a family of two free parameters (Q, QRS:
/// runs/two_parameter_solve.hpp), digits outside 10 … 300, and when every system asked for is
/// undefined for the body (a symmetric top for N, say).
solved_body solve_for_body(const solve_request& request);

}  // namespace rotlie::runs
