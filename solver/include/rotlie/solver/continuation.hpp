#pragma once
// Newton's method on the systems of the exact solver at one body (family_systems), from the
// solutions at a neighbouring body: N, H_R3's conditions P1 = P2 = 0 in two unknowns; R and P, the
// Lagrange system P1 = P2 = det[∇‖H_R5‖²; ∇P1; ∇P2] = 0 in three (critical_points.hpp). A start
// that does not converge fast to a regular, well separated solution is refused: the caller then
// uses the exact solver.
#include <array>
#include <optional>
#include <vector>

#include "rotlie/solver/family_systems.hpp"

namespace rotlie::solver {

using point3 = std::array<long double, 3>;  ///< the free coefficients (x_2 unused for N)

struct newton_limits {
  int max_iterations = 12;
  long double step_tolerance = 1e-14L;   ///< relative: |Δx| ≤ tol (1 + |x|) ends the iteration
  long double max_travel = 0.25L;        ///< |x − start| ≤ this × distance from start to the nearest other start
  long double min_condition = 1e-11L;    ///< 1 / (‖J‖ ‖J⁻¹‖), infinity norms, at the solution
};

/// The residual of the system at x and its Jacobian; nullopt when the Jacobian is singular there.
struct newton_result {
  point3 x{};
  bool converged = false;
  long double condition = 0;  ///< reciprocal condition number of the Jacobian at x
  int iterations = 0;
};
newton_result newton_solve(const numeric_system& system, const point3& start, const newton_limits& limits = {});

/// Every start (the solutions at the previous body) moved to the system's solution next to its
/// prediction (empty: the start itself; else one per start, extrapolated from the last two bodies);
/// nullopt when any fails the limits (no convergence, a near-singular Jacobian, a correction too
/// large for the distance to the other starts) or two reach the same solution. Same order as starts.
std::optional<std::vector<point3>> continue_solutions(const numeric_system& system, const std::vector<point3>& starts,
                                                      const std::vector<point3>& predicted = {},
                                                      const newton_limits& limits = {});

/// Each start moved as continue_solutions moves it, or nullopt where Newton refuses it (the others go on).
std::vector<std::optional<point3>> continue_each(const numeric_system& system, const std::vector<point3>& starts,
                                                 const newton_limits& limits = {});

/// ‖H_R5‖ (eq. 64) at x: sqrt(Σ q_m(x)²), body scaled to I3 = 1.
long double remainder_norm(const numeric_system& system, const point3& x);

}  // namespace rotlie::solver
