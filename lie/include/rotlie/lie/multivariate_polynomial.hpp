#pragma once
// Polynomials with exact rational coefficients in up to 16 unknowns (the free stage coefficients of a
// long scheme word: a 25-stage palindrome has 10 or 11): the coefficient ring of the symbolic
// remainders H_R5 … H_R9 of such words for a body with rational moments. coefficient_polynomial
// (4 unknowns, high degrees) stays the solver's ring for the elimination; this one trades the degree
// range for the number of unknowns: exponents are packed 4 bits per unknown into 64 bits, so a product
// is the sum of keys while every exponent stays at most 15 (checked through the total degree).
// Coefficients are integers over one denominator per polynomial: sums and products then never pay the
// gcd of every rational operation (the expansion of a long word does millions of them); the common
// factor is divided out when the denominator outgrows 64 bits, and on output.
#include <cln/integer.h>
#include <cln/rational.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/lie/coefficient_ring.hpp"

namespace rotlie::lie {

class multivariate_polynomial : public additive_operators<multivariate_polynomial> {
 public:
  static constexpr int max_unknowns = 16;
  static constexpr int max_degree = 15;  ///< total degree; every exponent is then ≤ 15 too
  struct term {
    std::uint64_t key;
    cln::cl_I numerator;  ///< the coefficient is numerator / denominator()
  };

  multivariate_polynomial() = default;
  multivariate_polynomial(const cln::cl_RA& constant);  // NOLINT: constants convert implicitly
  multivariate_polynomial(long constant) : multivariate_polynomial(cln::cl_RA(constant)) {}  // NOLINT
  /// The unknown x_k, k < max_unknowns.
  static multivariate_polynomial unknown(int k);

  static int exponent(std::uint64_t key, int k) { return static_cast<int>((key >> (4 * k)) & 15u); }
  static int key_degree(std::uint64_t key);

  const std::vector<term>& terms() const { return terms_; }  ///< sorted by key, no zero numerator
  const cln::cl_I& denominator() const { return denominator_; }
  /// (key, coefficient) in lowest terms, sorted by key.
  std::vector<std::pair<std::uint64_t, cln::cl_RA>> rational_terms() const;
  std::size_t size() const { return terms_.size(); }
  bool is_zero() const { return terms_.empty(); }
  int total_degree() const;  ///< −1 for zero

  cln::cl_RA operator()(const std::vector<cln::cl_RA>& x) const;
  /// Σ over the terms of |term(x)|: the size a value is compared with (cancellation-free scale).
  cln::cl_RA term_size(const std::vector<cln::cl_RA>& x) const;

  multivariate_polynomial& operator+=(const multivariate_polynomial& o);
  multivariate_polynomial& operator-=(const multivariate_polynomial& o);
  /// += k·o without the temporary k·o (the bracket expansion's inner step).
  multivariate_polynomial& add_multiple(const multivariate_polynomial& o, long k);
  multivariate_polynomial& operator*=(const cln::cl_RA& s);
  /// Throws std::overflow_error when the product's total degree would exceed max_degree.
  friend multivariate_polynomial operator*(const multivariate_polynomial& a, const multivariate_polynomial& b);
  friend bool operator==(const multivariate_polynomial& a, const multivariate_polynomial& b);

  /// One summand of sum_of_products: factor · a · b (b may be null: factor · a).
  struct product_term {
    cln::cl_RA factor;
    const multivariate_polynomial* a;
    const multivariate_polynomial* b;
  };
  /// Σ factor · a · b over one common denominator with a single sort: what a bracket or a series
  /// sum needs, without a polynomial per summand.
  static multivariate_polynomial sum_of_products(const std::vector<product_term>& summands);

  /// "3/2*x0^2*x3 - x1 + 1/5", unknowns named x0, x1, … (or by `names`).
  std::string to_string(const std::vector<std::string>& names = {}) const;

 private:
  void reduce();  ///< divides the numerators and the denominator by their gcd
  cln::cl_I denominator_ = 1;
  std::vector<term> terms_;
};

template <>
struct ring_traits<multivariate_polynomial> {
  static multivariate_polynomial from_int(long n) { return multivariate_polynomial(n); }
  static bool is_zero(const multivariate_polynomial& x) { return x.is_zero(); }
  static void normalize(multivariate_polynomial&) {}  // kept canonical up to the common factor
};

}  // namespace rotlie::lie
