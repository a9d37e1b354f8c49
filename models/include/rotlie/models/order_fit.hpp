#pragma once
// The one order fit: the least-squares slope of log(error) against log(h), over the points that
// measure the scheme. Which points those are is the rule's job, in one place: the finest ones (the
// asymptotic range), above the round-off floor of the scalar, and well above the exact
// reference's own estimated error.

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "rotlie/schemes/quad.hpp"

namespace rotlie::models {

/// A scheme error is attributed to the scheme only when it is this many times the reference's.
inline constexpr double reference_margin = 10;

struct protocol_point {
  double h = 0, h_over_cost = 0, error = 0;
  double reference_error = 0;  ///< the exact flow's estimated share of `error`
  /// The error belongs to the scheme: well above the reference's.
  bool attributable(double margin = reference_margin) const { return error > margin * reference_error; }
};

/// Errors at or below this are round-off of T, not the scheme's truncation error (the mean R^9
/// attitude error of the protocol's runs: a few hundred ε in double and long double, more in
/// float128 where the rotations' sines and cosines carry the error).
template <class T>
double round_off_floor() {
  if constexpr (std::is_same_v<T, double>)
    return 1e-13;
  else if constexpr (std::is_same_v<T, long double>)
    return 1e-16;
  else {
    static_assert(std::is_same_v<T, quad>, "a floor for this scalar");
    return 1e-28;
  }
}

/// Which points of a measurement (ordered coarse to fine) the slope is fitted over.
struct fit_rule {
  std::size_t finest = std::numeric_limits<std::size_t>::max();      ///< look only at the finest this many points
  std::size_t at_most = std::numeric_limits<std::size_t>::max();     ///< of those, keep at most this many, finest first
  double floor = 0;                 ///< leave out errors ≤ floor (round_off_floor<T>() in a protocol run)
  double margin = reference_margin; ///< leave out errors ≤ margin × reference error (0: keep every error > floor)
};

/// Least-squares slope of log(error) against log(h) over the points the rule selects, summed
/// finest first; NaN when fewer than two are selected.
inline double fitted_order(const std::vector<protocol_point>& points, const fit_rule& rule) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t seen = 0, kept = 0;
  for (std::size_t i = points.size(); i-- > 0 && seen < rule.finest && kept < rule.at_most; ++seen) {
    const auto& p = points[i];
    if (!(p.error > rule.floor && p.attributable(rule.margin))) continue;
    const double x = std::log(p.h), y = std::log(p.error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++kept;
  }
  if (kept < 2) return std::nan("");
  const double n = static_cast<double>(kept);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace rotlie::models
