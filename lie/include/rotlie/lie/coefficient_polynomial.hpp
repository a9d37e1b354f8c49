#pragma once
// Polynomials with exact rational coefficients in a few unknowns (the free stage coefficients of a
// scheme): the coefficient ring of the exact BCH path for a body with rational moments. GiNaC would
// do the same algebra, but the order conditions of one scheme cost milliseconds there and
// microseconds here; the solver then runs its elimination on these directly.
#include <cln/rational.h>

#include <array>
#include <cstdint>
#include <vector>

#include "rotlie/lie/coefficient_ring.hpp"

namespace rotlie::lie {

class coefficient_polynomial : public additive_operators<coefficient_polynomial> {
 public:
  static constexpr int max_unknowns = 4;
  using exponents = std::array<int, max_unknowns>;
  /// Exponents packed one byte per unknown: the product of monomials is the sum of keys while every
  /// exponent stays below 256 (degrees here stay below 40).
  struct term {
    std::uint32_t key;
    cln::cl_RA c;
  };

  coefficient_polynomial() = default;
  coefficient_polynomial(const cln::cl_RA& constant);  // NOLINT: constants convert implicitly
  coefficient_polynomial(long constant) : coefficient_polynomial(cln::cl_RA(constant)) {}  // NOLINT
  /// The unknown x_k, k < max_unknowns.
  static coefficient_polynomial unknown(int k);
  static coefficient_polynomial monomial(const exponents& e, const cln::cl_RA& c);

  /// The sum of the terms, in any order (equal keys added).
  static coefficient_polynomial from_terms(std::vector<term> terms);

  static exponents unpack(std::uint32_t key);
  static std::uint32_t pack(const exponents& e);

  const std::vector<term>& terms() const { return terms_; }  ///< sorted by key, no zero coefficient
  bool is_zero() const { return terms_.empty(); }
  bool is_constant() const { return terms_.empty() || (terms_.size() == 1 && terms_[0].key == 0); }
  int degree(int k) const;  ///< −1 for zero
  int total_degree() const;

  /// The coefficient of x_k^power, as a polynomial in the other unknowns.
  coefficient_polynomial coefficient(int k, int power) const;
  coefficient_polynomial derivative(int k) const;
  /// x_k ← value (exact).
  coefficient_polynomial substitute(int k, const cln::cl_RA& value) const;

  /// The same zero set with coprime integer coefficients (the product by a positive rational):
  /// integer arithmetic skips the gcd that every rational operation pays.
  coefficient_polynomial primitive_integer() const;

  cln::cl_RA operator()(const std::vector<cln::cl_RA>& x) const;
  double evaluate(const std::vector<double>& x) const;

  coefficient_polynomial& operator+=(const coefficient_polynomial& o);
  coefficient_polynomial& operator-=(const coefficient_polynomial& o);
  coefficient_polynomial& operator*=(const cln::cl_RA& s);
  friend coefficient_polynomial operator*(const coefficient_polynomial& a, const coefficient_polynomial& b);
  friend bool operator==(const coefficient_polynomial& a, const coefficient_polynomial& b);

 private:
  void combine_sorted(std::vector<term>&& unsorted);
  std::vector<term> terms_;
};

coefficient_polynomial power(const coefficient_polynomial& p, int n);

/// p / f when f divides p exactly, else false (q untouched): division on the leading term, which
/// leaves no remainder exactly when f | p because the packed key is a monomial order.
bool divide_exactly(const coefficient_polynomial& p, const coefficient_polynomial& f, coefficient_polynomial& q);

template <>
struct ring_traits<coefficient_polynomial> {
  static coefficient_polynomial from_int(long n) { return coefficient_polynomial(n); }
  static bool is_zero(const coefficient_polynomial& x) { return x.is_zero(); }
  static void normalize(coefficient_polynomial&) {}  // kept canonical by every operation
};

}  // namespace rotlie::lie
