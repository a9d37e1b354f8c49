#pragma once
// The systems the exact solver sets up at one body, for every body at once. H_R3 and H_R5 are
// homogeneous of degree 3 and 5 in w = (1/I1, 1/I2, 1/I3) (brackets of parts linear in w), so at
// w3 = 1 each coefficient of a condition, as a polynomial in the free stage coefficients x, is a
// polynomial of degree ≤ 5 in each of w1, w2. It is interpolated exactly (Newton form on the
// tensor grid w1, w2 ∈ {1, …, 6}) from 36 exact expansions, once per (scheme, permutation); at any
// body the conditions then cost one evaluation instead of one BCH expansion.
#include <cln/rational.h>

#include <array>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/coefficient_polynomial.hpp"

namespace rotlie::solver {

inline constexpr int interpolation_nodes = 6;  ///< per variable: degree ≤ 5 in each of w1, w2

/// A polynomial in x whose coefficients are polynomials in (w1, w2) at w3 = 1, in tensor Newton form.
struct body_polynomial {
  struct term {
    std::array<int, 3> x{0, 0, 0};                                              ///< exponents of x_0, x_1, x_2
    std::array<cln::cl_RA, interpolation_nodes * interpolation_nodes> exact;   ///< Newton coefficients c_ab
    std::array<long double, interpolation_nodes * interpolation_nodes> approx;  ///< the same, rounded
  };
  std::vector<term> terms;
  /// The polynomial in x at a rational body, exactly.
  lie::coefficient_polynomial at(const cln::cl_RA& w1, const cln::cl_RA& w2) const;
};

/// One (scheme, permutation) of a family: the conditions P1, P2 (coefficients of G1²G2² and G1²G3²
/// in H_R3) and every coefficient of H_R5, as the exact solver builds them.
struct body_system {
  std::string scheme, permutation;
  bch::scheme_layout layout;
  int unknowns = 0;  ///< 2 (N) or 3 (R, P)
  body_polynomial p1, p2;
  std::vector<body_polynomial> h5;
  /// Every monomial of p1, p2 and h5 once, and for each polynomial the row of each of its terms:
  /// Newton's method evaluates all of them at one point, sharing the monomials (numeric_system::stacked).
  std::vector<std::array<int, 3>> monomials;
  std::vector<std::vector<std::size_t>> rows;  ///< [polynomial: p1, p2, h5…][term]
};

/// One system, interpolated from its 36 exact expansions.
body_system interpolate_system(const std::string& scheme, const std::string& permutation);

/// Every system of the family (N, R, P) in the exact solver's order: scheme, then permutation
/// (bch::permutation_names). Costs 36 exact expansions per system; computed once per process.
const std::vector<body_system>& family_systems(const std::string& family);

/// A polynomial in x with long double coefficients: a condition at one body.
struct numeric_polynomial {
  struct term {
    std::array<int, 3> x{0, 0, 0};
    long double c = 0;
  };
  std::vector<term> terms;
  int max_degree = 0;
};

/// Several polynomials on one list of monomials: c[i * count + j] is polynomial j's coefficient of x^monomials[i].
struct stacked_polynomials {
  std::vector<std::array<int, 3>> monomials;
  std::vector<long double> c;
  std::size_t count = 0;
  int max_degree = 0;
};

struct numeric_system {
  int unknowns = 0;
  numeric_polynomial p1, p2;
  std::vector<numeric_polynomial> h5;
  stacked_polynomials stacked;  ///< p1, p2, h5…, for Newton on the Lagrange system
};

/// The system at the body (1/w1, 1/w2, 1), rounded to long double.
numeric_system evaluate_system(const body_system& system, long double w1, long double w2);

}  // namespace rotlie::solver
