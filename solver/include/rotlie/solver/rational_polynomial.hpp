#pragma once
// Univariate polynomials with exact rational coefficients: Euclid, square-free part, certified
// isolation (Descartes, with Sturm as a second method) of every real root, and refinement to any number of digits
// by exact bisection. Nothing here is approximate until the caller rounds a root.
#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>

#include <vector>

namespace rotlie::solver {

class rational_polynomial {
 public:
  rational_polynomial() = default;
  explicit rational_polynomial(std::vector<cln::cl_RA> coefficients);  ///< index = power

  int degree() const { return static_cast<int>(c_.size()) - 1; }  ///< −1 for the zero polynomial
  bool is_zero() const { return c_.empty(); }
  const std::vector<cln::cl_RA>& coefficients() const { return c_; }
  cln::cl_RA operator()(const cln::cl_RA& x) const;
  rational_polynomial derivative() const;

  friend rational_polynomial operator+(const rational_polynomial& a, const rational_polynomial& b);
  friend rational_polynomial operator-(const rational_polynomial& a, const rational_polynomial& b);
  friend rational_polynomial operator*(const rational_polynomial& a, const rational_polynomial& b);
  friend rational_polynomial remainder(const rational_polynomial& a, const rational_polynomial& b);
  friend rational_polynomial quotient(const rational_polynomial& a, const rational_polynomial& b);
  friend rational_polynomial gcd(rational_polynomial a, rational_polynomial b);  ///< monic
  /// p / gcd(p, p'): the same roots, each simple.
  rational_polynomial square_free() const;

 private:
  void trim();
  std::vector<cln::cl_RA> c_;
};

/// gcd(a, b) over Q, monic (modular_gcd.cpp): images modulo word-size primes, Chinese remaindering,
/// rational reconstruction, proved by exact division. The same result as gcd, without the growth of
/// Euclid's remainders over Q at high degree.
rational_polynomial modular_gcd(const rational_polynomial& a, const rational_polynomial& b);

/// True when gcd(p, p') = 1 modulo 2^61 − 1 with the degree kept: then p is square-free over Q.
/// False means "no certificate" (p may still be square-free).
bool square_free_certified_mod_prime(const rational_polynomial& p);

/// An interval (lo, hi] holding exactly one real root, or the root itself when lo == hi.
struct root_interval {
  cln::cl_RA lo, hi;
};

/// Every distinct real root of p (p ≠ 0), in increasing order: Descartes' rule of signs with
/// bisection on the primitive integer square-free part (descartes_isolation.cpp).
std::vector<root_interval> isolate_real_roots(const rational_polynomial& p);
/// The same for a p already known to be square-free (skips the gcd with p', the costly part at high degree).
std::vector<root_interval> isolate_real_roots_of_square_free(const rational_polynomial& p);
/// The same by Sturm sequences over Q: a second, independent method (slow beyond degree ~20).
std::vector<root_interval> isolate_real_roots_sturm(const rational_polynomial& p);

/// Shrinks an isolating interval of a square-free p by exact bisection until hi − lo ≤ width;
/// returns the midpoint (an exact rational within width/2 of the root).
cln::cl_RA refine_root(const rational_polynomial& square_free_p, root_interval r, const cln::cl_RA& width);

/// The same result as refine_root, faster: Newton's method safeguarded by bisection in floating point
/// of digits + 40 digits, then an exact certificate (p changes sign across x ± width/2 inside the
/// isolating interval); exact bisection only when the certificate fails. Built once per polynomial.
class root_polisher {
 public:
  root_polisher(const rational_polynomial& square_free_p, int digits);
  /// An exact rational within width/2 = 10^-(digits+10)/2 of the root isolated by r.
  cln::cl_RA polish(const root_interval& r) const;
  int uncertified() const { return uncertified_; }  ///< calls that needed the exact bisection

 private:
  int sign_at(const cln::cl_RA& x) const;
  const rational_polynomial& p_;
  int digits_;
  cln::cl_RA width_;
  std::vector<cln::cl_I> integer_;  ///< p times the lcm of its denominators
  std::vector<cln::cl_F> value_, slope_;  ///< p and p' rounded to the working precision
  mutable int uncertified_ = 0;
};

}  // namespace rotlie::solver
