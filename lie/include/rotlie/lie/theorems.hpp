#pragma once
// Theorems 1 and 2 of Laskar & Vaillant as predicates on monomials and coefficient vectors,
// and the upper bound they give on dim L_k.
#include <cln/integer.h>

#include <vector>

#include "rotlie/lie/monomial.hpp"
#include "rotlie/lie/polynomial.hpp"

namespace rotlie::lie {

/// Degree of the polynomials in L_k: Lie monomials of length k in quadratics have degree k + 1.
constexpr std::uint32_t degree_of_order(int order) { return static_cast<std::uint32_t>(order) + 1; }

/// Whether Theorem 1 allows monomial m in L_order.
/// order 2k:   G1^(2p+1) G2^(2q+1) G3^(2r+1), p+q+r = k−1                     (eq. 23)
/// order 2k+1: G1^(2p) G2^(2q) G3^(2r), p+q+r = k+1, p,q,r ≤ k, k ≥ 1          (eq. 24)
/// order 1 is outside the theorem; its "support" is the alphabet G1², G2², G3².
bool theorem1_allows(int order, const monomial& m);

/// All monomials Theorem 1 allows at this order, in monomial order; their count is
/// n_2k = k(k+1)/2 and n_2k+1 = k(k+5)/2 (section 2.4), and 3 at order 1.
std::vector<monomial> theorem1_monomials(int order);

/// The weight of Theorem 2 (eq. 35): Π (2p)!/(2^p p!) over the half-exponents = Π (2p−1)!!.
/// Precondition: all exponents even. It is the Gaussian moment E[G1^2p G2^2q G3^2r].
cln::cl_I theorem2_weight(const monomial& m);

/// Σ λ_pqr β_pqr (eq. 28) of a polynomial with rational coefficients; Theorem 2 says it is 0 on L_2k+1, k ≥ 1.
/// Precondition: every monomial has even exponents.
cln::cl_RA theorem2_pairing(const polynomial<cln::cl_RA>& x);

/// Whether Theorem 2 applies at this order (odd orders ≥ 3).
constexpr bool theorem2_applies(int order) { return order >= 3 && order % 2 == 1; }

/// The Theorem 1–2 upper bound on dim L_order: the Theorem 1 count, minus one at odd orders ≥ 3.
std::size_t theorem_bound(int order);

/// A basis of V_order = {polynomials on the Theorem 1 monomials satisfying Theorem 2},
/// with integer coefficients; dim V_order = theorem_bound(order).
std::vector<polynomial<cln::cl_RA>> theorem_space_basis(int order);

}  // namespace rotlie::lie
