#pragma once
// All real solutions of two polynomial equations in two unknowns with rational coefficients.
//
// Elimination: the resultant R(u) = Res_v(e1, e2) is univariate over Q; its real roots are isolated
// exactly (Descartes, on the square-free part) and each is certified to 10^-(digits+10) by an exact
// sign change (root_polisher).
//
// Back-substitution at a simple root u* of R: exactly one common root v of e1(u*, ·) and e2(u*, ·)
// lies above it, and it is real (a second one, or a complex pair, would make u* a multiple root).
// It is found from the double-precision roots of e(u*, ·), polished by Newton's method in v and
// then on (e1, e2) in (u, v) (regular at a simple intersection), in (digits + 30)-digit floating
// point, and accepted when both equations vanish to 10^-(digits+3) of the size of their terms. Every
// test is relative (the equations are first made primitive with integer coefficients): e1 = e2 = 0 and
// c1·e1 = c2·e2 = 0 give the same points for any nonzero c1, c2, e.g. a body in any unit. A
// simple root where both leading coefficients in v vanish is a point at infinity, not a solution.
//
// At a multiple root u* (several solutions above it, a tangency, a singular point or a point at
// infinity): when u* is rational, the real roots of gcd(e1(u*, ·), e2(u*, ·)) over Q, exactly;
// otherwise pairing.
//
// Pairing (at irrational multiple roots, as the fallback when any back-substitution fails, and as
// the second method of the tests): the real roots of Res_u(e1, e2), certified, and every pair tested
// exactly against the u's concerned.
#include <cln/rational.h>

#include <string>
#include <vector>

#include "rotlie/lie/coefficient_polynomial.hpp"
#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {

struct real_point {
  cln::cl_RA u, v;         ///< exact rationals within 10^-(digits+10) of the solution
  cln::cl_RA residual;     ///< max |e_i(u, v)| / (size of e_i's terms) at these values: relative
};

enum class solve_method { automatic, pairing };

struct system_result {
  bool degenerate = false;  ///< the equations share a factor: a curve of solutions, not isolated points
  std::string note;         ///< why, when degenerate
  std::vector<real_point> points;  ///< sorted by u, then v
  int resultant_degree_u = 0;      ///< degree of Res_v(e1, e2)
  int real_roots_u = 0;            ///< distinct real roots of it that were isolated (count_real_eliminant_roots)
  bool paired = false;             ///< every root paired (requested, or the fallback)
  int multiple_roots = 0;          ///< irrational real multiple roots of R, paired against Res_u
  double seconds_elimination = 0;  ///< common-factor check and resultant(s)
  double seconds_roots = 0;        ///< isolation, refinement, back-substitution or pairing, checks
};

/// e1 = e2 = 0 over the reals, to `digits` significant digits (≥ 10). e1 and e2 are polynomials
/// in the unknowns x_u and x_v only. multiple_factor: a polynomial in u whose roots the caller knows
/// to be multiple roots of the eliminant (spurious points); they are kept once, not certified away.
system_result solve_two_equations(const lie::coefficient_polynomial& e1, const lie::coefficient_polynomial& e2, int u,
                                  int v, int digits, solve_method method = solve_method::automatic,
                                  const rational_polynomial& multiple_factor = rational_polynomial());

/// The number of distinct real roots of the eliminant that solve_two_equations isolates (the same
/// reduction), without solving: −1 where it reports the system degenerate. Cheaper than a solve by
/// the back-substitution, the pairing and the refinement.
int count_real_eliminant_roots(const lie::coefficient_polynomial& e1, const lie::coefficient_polynomial& e2, int u, int v,
                               const rational_polynomial& multiple_factor = rational_polynomial());

}  // namespace rotlie::solver
