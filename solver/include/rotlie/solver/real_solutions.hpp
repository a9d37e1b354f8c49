#pragma once
// All real solutions of two polynomial equations in two unknowns with rational coefficients.
//
// Elimination: the resultant R(u) = Res_v(e1, e2) is univariate over Q; its real roots are isolated
// exactly (Descartes) and each is certified to 10^-(digits+10) by an exact sign change of R.
//
// Back-substitution: when R is square-free, a real root u* carries exactly one common root v of
// e1(u*, ·) and e2(u*, ·), and it is real (a second one, or a complex pair, would make u* a multiple
// root of R). It is found from the double-precision roots of e(u*, ·), polished by Newton's method
// on (e1, e2) in (digits + 30)-digit floating point, and accepted when both equations vanish to
// 10^-(digits+3) of the size of their terms, evaluated exactly.
//
// Above a real multiple root u* of R (several common roots, or a tangency), every real root of
// e1(u*, ·) and of e2(u*, ·) is polished by Newton's method in v and kept when both vanish.
//
// Pairing (the fallback, and the second method of the tests): the resultants in each unknown, their
// real roots certified, and every pair tested exactly. Used for every root when any
// back-substitution fails its check. A simple root of R where both leading coefficients in v
// vanish is a point at infinity, not a solution.
#include <cln/rational.h>

#include <string>
#include <vector>

#include "rotlie/lie/coefficient_polynomial.hpp"
#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {

struct real_point {
  cln::cl_RA u, v;         ///< exact rationals within 10^-(digits+10) of the solution
  cln::cl_RA residual;     ///< max |e_i(u, v)| at these values
};

enum class solve_method { automatic, pairing };

struct system_result {
  bool degenerate = false;  ///< the equations share a factor: a curve of solutions, not isolated points
  std::string note;         ///< why, when degenerate
  std::vector<real_point> points;  ///< sorted by u, then v
  int resultant_degree_u = 0;      ///< degree of Res_v(e1, e2)
  bool paired = false;             ///< every root paired (requested, or the fallback)
  int multiple_roots = 0;          ///< real multiple roots of R, each solved above by solve_above (below)
  double seconds_elimination = 0;  ///< common-factor check and resultant(s)
  double seconds_roots = 0;        ///< isolation, refinement, back-substitution or pairing, checks
};

/// e1 = e2 = 0 over the reals, to `digits` significant digits (≥ 10). e1 and e2 are polynomials
/// in the unknowns x_u and x_v only. multiple_factor: a polynomial in u whose roots the caller knows
/// to be multiple roots of the eliminant (spurious points); they are kept once, not certified away.
system_result solve_two_equations(const lie::coefficient_polynomial& e1, const lie::coefficient_polynomial& e2, int u,
                                  int v, int digits, solve_method method = solve_method::automatic,
                                  const rational_polynomial& multiple_factor = rational_polynomial());

}  // namespace rotlie::solver
