#pragma once
// GiNaC expressions as coefficients: symbolic moments of inertia and stage coefficients.
// Kept apart from coefficient_ring.hpp so that exact-rational users do not pull in GiNaC.
#include <ginac/ginac.h>

#include "rotlie/lie/coefficient_ring.hpp"

namespace rotlie::lie {

template <>
struct ring_traits<GiNaC::ex> {
  static GiNaC::ex from_int(long n) { return GiNaC::ex(n); }
  /// Exact: the coefficient is kept expanded (see normalize), and an expanded polynomial is zero iff it is 0.
  static bool is_zero(const GiNaC::ex& x) { return x.is_zero(); }
  static void normalize(GiNaC::ex& x) { x = x.expand(); }
};

}  // namespace rotlie::lie
