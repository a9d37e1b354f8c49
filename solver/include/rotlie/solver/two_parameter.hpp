#pragma once
// Dedicated 4th-order schemes with two free parameters (beyond LV section 3, which stops at one: the
// R and P families). A palindrome whose first-order conditions leave four free coefficients (13-stage
// ABC words, 11-stage RS words) meets the two order-4 conditions P1 = P2 = 0 (dim L3 = 2, the
// coefficients of G1²G2² and G1²G3² in H_R3) on a 2-dimensional real surface. On it we minimise
// f = ‖H_R5‖² (LV eq. (64), the norm of the maps) as LV do on the P curve, but numerically: descent
// on the surface (reduced Newton steps in its tangent plane, restored onto P1 = P2 = 0 by
// minimum-norm Gauss–Newton) from many random starts, each local minimum then polished as a root of
// the Lagrange system ∇f = λ1 ∇P1 + λ2 ∇P2, P1 = P2 = 0 in CLN long floats. What is certified, exactly
// at the written decimals: order 4 (table_certificate) and a vanishing projected gradient. What is
// not: that the smallest minimum found is the global one (the counts of starts and of distinct minima
// are reported). The same code takes three free coefficients (a curve: R, P), which checks it against
// the exact elimination of dedicated_schemes.
#include <cln/rational.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/multivariate_polynomial.hpp"
#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::solver {

/// The constrained problem of one (word, permutation) at one body, exact in the free coefficients.
struct two_parameter_system {
  bch::scheme_layout layout;
  lie::moments_of_inertia body;  ///< scaled to I3 = 1
  lie::multivariate_polynomial p1, p2;            ///< H_R3 on G1²G2² and G1²G3²
  std::vector<lie::multivariate_polynomial> h5;   ///< every coefficient of H_R5
  lie::multivariate_polynomial norm_squared;      ///< Σ h5² = ‖H_R5‖² (eq. 64)
  std::vector<lie::multivariate_polynomial> gradient, p1_gradient, p2_gradient;  ///< ∂/∂x_k
  int free_count() const { return static_cast<int>(layout.free_coefficients.size()); }
};

/// Throws std::invalid_argument unless the word is a palindrome with 3 or 4 free coefficients.
two_parameter_system two_parameter_conditions(const bch::scheme_layout& layout, const lie::moments_of_inertia& body);

struct minimum_search_options {
  int starts = 40;
  double box = 1.0;  ///< starts uniform in [−box, box]^n, then moved onto the surface
  std::uint64_t seed = 1;
  int max_iterations = 150;
  double bound = 5;  ///< a descent that leaves |x_k| ≤ bound is abandoned (no practical scheme there)
};

struct local_minimum {
  std::vector<long double> x;
  std::array<long double, 2> lambda{};  ///< Lagrange multipliers of P1, P2
  double remainder = 0;                 ///< ‖H_R5‖ = √f
  int hits = 1;                         ///< starts that ended there
};

struct minimum_search {
  std::vector<local_minimum> minima;  ///< distinct, by ascending ‖H_R5‖
  int starts = 0;
  int on_surface = 0;  ///< starts that reached P1 = P2 = 0
  int converged = 0;   ///< descents that ended at a local minimum (reduced Hessian positive definite)
};

minimum_search search_minima(const two_parameter_system& s, const minimum_search_options& o);

/// A local minimum polished and written with `digits` significant digits, with its certificates.
struct certified_minimum {
  std::vector<cln::cl_RA> x;                   ///< free coefficients as written
  std::map<std::string, cln::cl_RA> values;    ///< every stage coefficient as written
  cln::cl_RA order_residual;                   ///< certify_order_four's residual (order 4 when ≤ 10^-(digits-5))
  int order = 0;                               ///< certify_order_four's verdict
  /// max_k |(∇f − λ1∇P1 − λ2∇P2)_k| / Σ|terms of ∂f/∂x_k|, λ the exact least-squares multipliers at x
  cln::cl_RA projected_gradient;
  double remainder = 0;                        ///< ‖H_R5‖ at x
  std::vector<double> reduced_hessian;         ///< eigenvalues of the Lagrangian's Hessian on the tangent plane
  bool is_minimum() const;
};

/// Newton on the Lagrange system in CLN long floats at digits + 25 digits; throws std::runtime_error
/// when it does not converge (a degenerate critical point).
certified_minimum polish_minimum(const two_parameter_system& s, const local_minimum& m, int digits);

/// The exact projected gradient (as in certified_minimum) at free values x.
cln::cl_RA projected_gradient(const two_parameter_system& s, const std::vector<cln::cl_RA>& x);

/// Scheme table text (docs/scheme_table_format.md), `order 4`, analytic_remainder ‖H_R5‖.
std::string two_parameter_table_text(const two_parameter_system& s, const certified_minimum& m, int digits,
                                     const lie::moments_of_inertia& body, const std::string& name, const std::string& source);

/// The words of the family: 13-stage ABC palindromes (first-appearance naming), or the 11-stage RS ones
/// (RSRSRSRSRSR and SRSRSRSRSRS: R and S are different parts, so both orders count).
std::vector<std::string> two_parameter_words(bch::splitting split);

struct two_parameter_entry {
  std::string word, permutation;
  bch::splitting split = bch::splitting::abc;
  minimum_search search;
  bool polished = false;
  certified_minimum best;  ///< the smallest minimum found, polished (when polished)
  std::string note;        ///< why not polished
};

struct two_parameter_result {
  std::vector<two_parameter_entry> entries;  ///< by ascending best ‖H_R5‖; systems without minima last
  double seconds = 0;                        ///< CPU
};

/// Every (word, permutation) of the splitting at the body: search, then polish each system's best,
/// or only the `polish` systems whose best minimum is smallest (polish < 0: all).
two_parameter_result solve_two_parameter(const lie::moments_of_inertia& body, bch::splitting split,
                                         const std::vector<std::string>& words, const std::vector<std::string>& permutations,
                                         const minimum_search_options& o, int digits, int polish = -1);

}  // namespace rotlie::solver
