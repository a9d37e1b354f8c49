#pragma once
// Exact arithmetic in Q(α) for a real algebraic α isolated in (lo, hi] as a root of a square-free
// rational polynomial S: elements are polynomials in u reduced modulo S. When an element shares a
// factor with S (S reducible), S is replaced by the factor that vanishes at α (dynamic evaluation,
// "D5"), so no factorisation is ever needed. Used for the gcd in v of two bivariate polynomials
// above an irrational multiple root of their resultant.
#include <cln/rational.h>

#include <vector>

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {

class residue_field {
 public:
  /// modulus: square-free, with exactly one root in (lo, hi], the α meant.
  residue_field(rational_polynomial modulus, const cln::cl_RA& lo, const cln::cl_RA& hi);

  const rational_polynomial& modulus() const { return modulus_; }
  rational_polynomial reduce(const rational_polynomial& a) const;
  /// a(α) = 0, exactly (may shrink the modulus to the factor that vanishes at α).
  bool is_zero(const rational_polynomial& a);
  rational_polynomial inverse(const rational_polynomial& a);
  rational_polynomial times(const rational_polynomial& a, const rational_polynomial& b) const;

  /// Monic gcd of two polynomials in v whose coefficients (index = power of v) are elements.
  std::vector<rational_polynomial> gcd_in_v(std::vector<rational_polynomial> a, std::vector<rational_polynomial> b);
  /// a / b for b dividing a exactly (the remainder is dropped).
  std::vector<rational_polynomial> quotient_in_v(std::vector<rational_polynomial> a, const std::vector<rational_polynomial>& b);

 private:
  bool holds_root(const rational_polynomial& q) const;
  rational_polynomial modulus_;
  cln::cl_RA lo_, hi_;
};

}  // namespace rotlie::solver
