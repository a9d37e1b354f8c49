#pragma once
// All complex solutions of one R/P system (the Lagrange system P1 = P2 = det[∇f; ∇P1; ∇P2] = 0 of
// critical_points.hpp, f = ‖H_R5‖² = Σ q²) carried between bodies by a parameter homotopy in
// (w1, w2) = (1/I1, 1/I2) at I3 = 1. Real solutions are born and die in pairs where a complex
// conjugate pair reaches the real axis; continuing every complex solution sees those births, which
// continuing the real ones cannot. The parameters move along two straight segments through a random
// complex point (the "gamma trick"): the discriminant has real codimension two in the complex
// parameter plane, so a generic path misses it and no two solutions collide on the way.
#include <array>
#include <complex>
#include <vector>

#include <cln/rational.h>

#include "rotlie/solver/family_systems.hpp"

namespace rotlie::solver {

using complex_ld = std::complex<long double>;
using complex_point = std::array<complex_ld, 3>;
using complex_body = std::array<complex_ld, 2>;  ///< (w1, w2), complex on the way between two bodies

/// The three equations at one (complex) body, each expanded as a polynomial in x: a point then costs
/// the values and first derivatives of three polynomials (no Hessian of H_R5's coefficients).
struct lagrange_polynomials {
  struct term {
    std::array<int, 3> x{0, 0, 0};
    complex_ld c;
  };
  std::array<std::vector<term>, 3> equations;
  int max_degree = 0;
};

/// The system at (w1, w2), from the interpolated coefficients (long double, as evaluate_system).
lagrange_polynomials lagrange_at(const body_system& system, const complex_body& w);

/// F(x) and its Jacobian.
void lagrange_residual(const lagrange_polynomials& p, const complex_point& x, complex_point& F,
                       std::array<complex_point, 3>& J);

struct tracking_stats {
  long long newton_iterations = 0;  ///< residual + Jacobian evaluations
  long long assemblies = 0;         ///< lagrange_at calls
  int refused_steps = 0;
  int loops = 0;                    ///< monodromy loops
};

/// Every solution in `x` (solutions at w_from) carried to w_to along w_from → w_from + (w_to − w_from)/2
/// + γ |w_to − w_from| → w_to, all paths with the same steps (one assembly per step serves them all),
/// the step (first `first_step` of the path) halved when any path's Newton corrector does not contract. false when the steps fall
/// below the floor, a path diverges, or two endpoints coincide (path jumping): the caller decides.
bool track_all(const body_system& system, std::vector<complex_point>& x, const complex_body& w_from,
               const complex_body& w_to, complex_ld gamma, tracking_stats& stats, long double first_step = 0.125L);

/// Solutions found by monodromy: from the seeds (solutions at w), loops w → a → b → w through random
/// complex bodies permute the solutions; new endpoints are added until `target` are known or
/// `max_loops` loops in a row bring nothing new (triangles of size about `radius` × |w|). Returns the distinct solutions found.
std::vector<complex_point> monodromy_solutions(const body_system& system, std::vector<complex_point> seeds,
                                               const complex_body& w, std::size_t target, int max_loops,
                                               unsigned seed, tracking_stats& stats, long double radius = 0.2L);

/// Newton on the system at a real body w from x (complex); the residual after, relative to the terms.
struct polished_point {
  complex_point x{};
  long double correction = 0;  ///< size of the last Newton step, relative to 1 + |x|
  bool converged = false;
};
polished_point polish(const lagrange_polynomials& p, complex_point x, int iterations = 6);

/// Every finite complex solution at a rational body from the exact elimination of
/// critical_points.cpp: the complex roots of the eliminant's square-free part (Aberth, long double),
/// the other unknown from the quadratic planar equation where the planar determinant vanishes too,
/// x_eliminated = −B/A, each Newton-polished on the Lagrange system.
struct eliminant_start {
  std::vector<complex_point> x;  ///< distinct, polished
  int eliminant_degree = 0;      ///< with multiplicity
  int distinct_roots = 0;        ///< of the eliminant
  int at_infinity = 0;           ///< candidates where the linear solve is undefined (A = 0), before or after polish
  int unpolished = 0;            ///< candidates where Newton did not converge
  int singular = 0;              ///< candidates that converged where the Jacobian is singular (a curve of solutions)
};
eliminant_start start_from_eliminant(const body_system& system, const cln::cl_RA& w1, const cln::cl_RA& w2);

}  // namespace rotlie::solver
