#pragma once
// All real solutions of two polynomial equations in two unknowns with rational coefficients:
// the resultants in each unknown are univariate over Q, their real roots are isolated (Sturm)
// and refined exactly, and every pair of roots is tested by exact evaluation. A pair is a
// solution when both equations vanish to within the refinement width, which roots that are
// not solutions cannot meet (the value there is a fixed nonzero algebraic number).
#include <cln/rational.h>
#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace rotlie::solver {

struct real_point {
  cln::cl_RA u, v;         ///< exact rationals within 10^-(digits+10) of the solution
  cln::cl_RA residual;     ///< max |e_i(u, v)| at these values
};

struct system_result {
  bool degenerate = false;  ///< the equations share a factor: a curve of solutions, not isolated points
  std::string note;         ///< why, when degenerate
  std::vector<real_point> points;  ///< sorted by u, then v
  int resultant_degree_u = 0, resultant_degree_v = 0;
  double seconds_elimination = 0;  ///< gcd check and the two resultants
  double seconds_roots = 0;        ///< square-free parts, isolation, refinement and pairing
};

/// e1 = e2 = 0 over the reals, to `digits` significant digits (≥ 10).
system_result solve_two_equations(const GiNaC::ex& e1, const GiNaC::ex& e2, const GiNaC::symbol& u,
                                  const GiNaC::symbol& v, int digits);

}  // namespace rotlie::solver
