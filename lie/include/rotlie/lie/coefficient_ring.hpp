#pragma once
// What lie::polynomial needs from its coefficient type: zero, integers, exact zero test,
// and a normal form (a no-op for numbers, expansion for symbolic expressions).
#include <cln/rational.h>
#include <cln/rational_io.h>

namespace rotlie::lie {

template <class R>
struct ring_traits;

/// Exact rationals: proofs, dimensions, order conditions with rational data.
template <>
struct ring_traits<cln::cl_RA> {
  static cln::cl_RA from_int(long n) { return cln::cl_RA(n); }
  static bool is_zero(const cln::cl_RA& x) { return cln::zerop(x); }
  static void normalize(cln::cl_RA&) {}
};

/// Plain doubles: numeric evaluation only. Zero means exactly zero (no tolerance is hidden here).
template <>
struct ring_traits<double> {
  static double from_int(long n) { return static_cast<double>(n); }
  static bool is_zero(double x) { return x == 0.0; }
  static void normalize(double&) {}
};

/// a + b, a − b and −a of a polynomial type P from its own +=, −= and *= by a rational (both
/// polynomial types derive from it, so that they define them once).
template <class P>
struct additive_operators {
  friend P operator+(P a, const P& b) { return a += b; }
  friend P operator-(P a, const P& b) { return a -= b; }
  friend P operator-(P a) { return a *= cln::cl_RA(-1); }
};

}  // namespace rotlie::lie
