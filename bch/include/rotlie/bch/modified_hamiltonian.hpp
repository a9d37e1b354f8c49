#pragma once
// The modified Hamiltonian hK = hH + Σ_{k≥2} h^k H_Rk of a splitting scheme (eq. 12), computed
// by nested BCH series evaluated in the Lie–Poisson algebra, with GiNaC coefficients that are
// polynomials in the free stage coefficients and in the inverse moments of inertia.
#include <ginac/ginac.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/coefficient_polynomial.hpp"
#include "rotlie/lie/coefficient_ring_ginac.hpp"
#include "rotlie/lie/polynomial.hpp"

namespace rotlie::bch {

using symbolic_polynomial = lie::polynomial<GiNaC::ex>;

/// Inverse moments of inertia w_i = 1/I_i: symbols, exact rationals or numbers.
struct inverse_inertia {
  GiNaC::ex w1, w2, w3;
  /// Symbols w1, w2, w3 (the general body), the same symbols on every call.
  static inverse_inertia symbolic();
  /// The paper's ABC variables, scaled by 2I1 = 1: 1/I2 = 2(1+x), 1/I3 = 2(1+y) (eq. 54).
  static inverse_inertia abc_paper(const GiNaC::symbol& x, const GiNaC::symbol& y);
  /// The paper's RS variables, scaled by 2I1 = 1: x = I1/I2, y = I1/I3 (eq. 43).
  static inverse_inertia rs_paper(const GiNaC::symbol& x, const GiNaC::symbol& y);
  const GiNaC::ex& operator[](int axis) const { return axis == 1 ? w1 : axis == 2 ? w2 : w3; }
};

/// The Hamiltonian part of one letter after the permutation:
/// ABC: A, B, C = G_i²/(2I_i) (eqs. 4–6); RS with permutation P = p1 p2 p3:
/// R = G_p1²/2 (1/I_p1 − 1/I_p2), S = G_p3²/2 (1/I_p3 − 1/I_p2) + G²/(2I_p2) (eqs. 8–9).
symbolic_polynomial part_hamiltonian(char letter, splitting split, const std::string& permutation,
                                     const inverse_inertia& w);

struct modified_hamiltonian {
  int max_order = 0;
  /// remainder[k] = H_Rk for k = 1 … max_order (remainder[1] = H when the first-order conditions hold).
  std::vector<symbolic_polynomial> remainder;
};

/// The stages as Lie-algebra elements x_i = c_i X_i (h implicit: order k ↔ polynomial degree k+1).
struct stage_element {
  GiNaC::ex coefficient;
  symbolic_polynomial part;
};

/// Largest order supported (the symmetric BCH series is computed to this degree).
inline constexpr int max_remainder_order = 9;

/// Palindromic stage lists use nested symmetric BCH; others nested BCH from the left
/// (the first stage acts first). Throws std::invalid_argument for order < 1 or > max_remainder_order.
modified_hamiltonian compute_modified_hamiltonian(const std::vector<stage_element>& stages, int max_order);

/// The same expansion for a body with rational moments, without GiNaC: every coefficient is an exact
/// polynomial in the free stage coefficients, which are the unknowns x_0, x_1, … in the order of
/// layout.free_coefficients (the eliminated ones solve the first-order conditions). This is the
/// solver's input: the same H_Rk as compute_modified_hamiltonian, in microseconds per order.
using exact_polynomial = lie::polynomial<lie::coefficient_polynomial>;
struct exact_modified_hamiltonian {
  int max_order = 0;
  std::vector<std::string> unknowns;           ///< names of x_0, x_1, …
  std::vector<exact_polynomial> remainder;     ///< remainder[k] = H_Rk
  std::map<std::string, lie::coefficient_polynomial> coefficient_values;  ///< every stage coefficient's name → its value
};
/// w = (1/I1, 1/I2, 1/I3). Throws std::invalid_argument as compute_modified_hamiltonian.
exact_modified_hamiltonian compute_exact_modified_hamiltonian(const scheme_layout& layout,
                                                              const std::array<cln::cl_RA, 3>& w, int max_order);

/// The same at numeric stage-coefficient values (name → value), in double: the analytic remainder of
/// a solution, where three digits are all that is asked and the exact expansion would cost more.
std::vector<lie::polynomial<double>> compute_numeric_modified_hamiltonian(const scheme_layout& layout,
                                                                          const std::array<cln::cl_RA, 3>& w,
                                                                          const std::map<std::string, double>& values,
                                                                          int max_order);

/// part_hamiltonian with rational inverse moments.
lie::polynomial<cln::cl_RA> rational_part_hamiltonian(char letter, splitting split, const std::string& permutation,
                                                     const std::array<cln::cl_RA, 3>& w);

/// Σ λ_pqr β_pqr of eq. (28) for a polynomial with even exponents (eq. 63 at order 5): Theorem 2
/// says it vanishes on odd orders ≥ 3.
GiNaC::ex theorem2_pairing(const symbolic_polynomial& x);

/// Convenience: a laid-out scheme with its coefficient values and body.
std::vector<stage_element> stage_elements(const scheme_layout& layout, const coefficient_symbols& coefficients,
                                          const inverse_inertia& w);

}  // namespace rotlie::bch
