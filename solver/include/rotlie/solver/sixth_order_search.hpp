#pragma once
// Dedicated 6th-order schemes (beyond LV section 3): for a palindromic word and a body, H_R3 = H_R5 = 0
// is dim L3 + dim L5 = 2 + 6 conditions on the free stage coefficients (the first-order conditions
// eliminate one coefficient per part); a word with as many free coefficients as conditions has
// isolated solutions. Exact elimination does not scale to 8 unknowns of degree 5, so the real
// solutions are sought by damped Newton from many random starts (double), each root found is
// polished in CLN long floats to digits + 25 digits, and the printed decimals are certified by
// evaluating every exact condition at them relative to the size of its terms (as table_certificate
// does at order 4). Nothing here proves that every real solution was found: the count of distinct
// roots against the number of starts is reported so that the reader can judge.
#include <cln/rational.h>

#include <cstdint>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/multivariate_polynomial.hpp"
#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::solver {

/// A polynomial in n unknowns compiled for floating-point evaluation with its gradient.
struct compiled_polynomial {
  int unknowns = 0;
  std::vector<std::uint8_t> exponents;  ///< unknowns per term
  std::vector<long double> coefficients;
  explicit compiled_polynomial(const lie::multivariate_polynomial& p = {}, int n = 0);
};

struct sixth_order_system {
  bch::scheme_layout layout;
  std::array<cln::cl_RA, 3> w;  ///< inverse moments of the body scaled to I3 = 1
  /// Every coefficient of H_R3 and H_R5 (Theorem 1's monomials), exact, in the free coefficients.
  std::vector<lie::multivariate_polynomial> all_conditions;
  std::vector<std::string> condition_names;  ///< "H_R3 G1^2G2^2", …
  /// The independent ones: each order's last monomial dropped (Theorem 2 fixes it from the others).
  std::vector<compiled_polynomial> conditions;
  int free_count() const { return static_cast<int>(layout.free_coefficients.size()); }
};

/// Throws std::invalid_argument when the word is not a palindrome.
sixth_order_system sixth_order_conditions(const bch::scheme_layout& layout, const lie::moments_of_inertia& body);

struct search_options {
  int starts = 200;
  double box = 1.0;            ///< starts uniform in [−box, box]^n
  std::uint64_t seed = 1;
  int max_iterations = 60;
  int first_start = 0;         ///< skip this many starts of the seed's sequence (a resumed search)
};

struct newton_root {
  std::vector<long double> x;  ///< free coefficients
  double residual = 0;         ///< max |condition| / Σ|terms| at x (long double)
  int hits = 1;                ///< starts that converged to it
};

struct search_result {
  std::vector<newton_root> roots;  ///< distinct, by ascending first coefficient
  int starts = 0, converged = 0;
};

/// Damped Newton from `starts` random points on a square system (conditions.size() == free_count()).
search_result newton_search(const sixth_order_system& s, const search_options& o);

/// The root refined to `digits` + 25 digits (Newton in CLN long floats), then written with `digits`
/// significant digits and read back exactly: the values a table prints.
std::vector<cln::cl_RA> polished_root(const sixth_order_system& s, const std::vector<long double>& x, int digits);

/// σ_min / σ_max of the Jacobian of the scaled independent conditions (each row divided by Σ|terms|) at
/// x: near 0 where the root is not isolated (the solution set is a curve or more through it).
double jacobian_condition_ratio(const sixth_order_system& s, const std::vector<long double>& x);

/// max over every condition of H_R3, H_R5 and the first-order conditions of |value| / Σ|terms| at the
/// free values x (exact rationals); the eliminated coefficients are their written `digits` decimals.
cln::cl_RA sixth_order_residual(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits);

/// Every stage coefficient's name → value, the eliminated ones as written with `digits` digits.
std::map<std::string, cln::cl_RA> all_coefficients(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits);

/// ‖H_R7‖: the Euclidean norm of H_R7's coefficients on Theorem 1's monomials, body scaled to I3 = 1,
/// at the stage values (name → value); the same measure for any palindromic table of the splitting.
double remainder7_norm(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                       const std::map<std::string, double>& values);

/// Palindromes of `length` stages in the splitting, as the naming of scheme_word sees them: letters in
/// order of first appearance (ABC words start with AB), no letter twice in a row, every part acting.
std::vector<std::string> palindromic_words(int length, bch::splitting split);

/// The scheme table text (docs/scheme_table_format.md) of a certified 6th-order solution.
std::string sixth_order_table_text(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits,
                                   const lie::moments_of_inertia& body, const std::string& name, const std::string& source);

}  // namespace rotlie::solver
