#pragma once
// The resultant of two bivariate polynomials with rational coefficients, by evaluation and
// interpolation: at deg + 1 integer values of the kept unknown, Res(a, b) = α^(n − deg r) Res(a, r)
// with r the pseudo-remainder of the higher-degree polynomial by the lower one, whose Sylvester
// determinant is small and taken over the integers (fraction-free Bareiss); the exact polynomial is
// rebuilt by Newton interpolation. Same result as GiNaC::resultant up to a constant factor.
#include "rotlie/lie/coefficient_polynomial.hpp"

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {

/// Res_v(p, q) as a polynomial in u, scaled to integer coefficients (the scale does not move roots).
/// p, q are polynomials in the unknowns x_eliminated and x_kept only (std::invalid_argument otherwise).
rational_polynomial resultant_in(const lie::coefficient_polynomial& p, const lie::coefficient_polynomial& q, int eliminated,
                                 int kept);

/// Determinant of a square integer matrix (row-major), fraction-free Gaussian elimination.
cln::cl_I bareiss_determinant(std::vector<std::vector<cln::cl_I>> m);

}  // namespace rotlie::solver
