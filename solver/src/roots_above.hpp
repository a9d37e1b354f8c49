#pragma once
// Internal to the solver: the common roots of e1(u0, ·) and e2(u0, ·) above a certified root u0 of
// the eliminant R = Res_v(e1, e2) — by Newton's method above a simple root, exactly above a multiple
// one (a gcd over Q at a rational root, over Q(α) at an irrational one).
#include <cln/rational.h>

#include <optional>
#include <vector>

#include "bivariate_rows.hpp"
#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/real_solutions.hpp"

namespace rotlie::solver::detail {

/// e1, e2 and their derivatives in u, as rows in floating point, for back-substitution.
struct float_system {
  float_system(const coefficient_polynomial& p1, const coefficient_polynomial& p2, int u, int v,
               const cln::float_format_t& format)
      : e1(p1, u, v, format), e2(p2, u, v, format), e1_u(p1.derivative(u), u, v, format), e2_u(p2.derivative(u), u, v, format) {}
  float_bivariate_rows e1, e2, e1_u, e2_u;
};

/// The one common root above a simple root u0 of R (certified to 10^-(digits+10)/2), or nullopt.
std::optional<real_point> common_root_above(const float_system& f, const cln::cl_RA& u0, int digits);

/// The simplest rational in [lo, hi] (smallest denominator).
cln::cl_RA simplest_rational_between(const cln::cl_RA& lo, const cln::cl_RA& hi);

/// Every real common root above the rational u = r, exactly.
std::vector<real_point> common_roots_above_rational(const coefficient_polynomial& e1, const coefficient_polynomial& e2,
                                                    int u, int v, const cln::cl_RA& r, int digits);

/// Every real common root above the irrational root of `square_free` isolated by `interval`, which is
/// also a root of `multiple` (square-free); nullopt when a step does not conclude.
std::optional<std::vector<real_point>> common_roots_above_algebraic(const coefficient_polynomial& e1,
                                                                    const coefficient_polynomial& e2, int u, int v,
                                                                    const rational_polynomial& square_free,
                                                                    const rational_polynomial& multiple,
                                                                    const root_interval& interval, int digits);

}  // namespace rotlie::solver::detail
