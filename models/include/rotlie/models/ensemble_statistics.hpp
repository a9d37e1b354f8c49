#pragma once
// The statistics the md experiments report: a mean with its standard error (over runs, or over blocks
// of one run taken as independent), and the Kolmogorov–Smirnov distance of a sample from the standard
// normal with its critical value (the Maxwell–Boltzmann checks of the thermostats).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace rotlie::models {

/// Mean and standard error of the mean (sample standard deviation / √n); the error of one value is
/// unknown (NaN), not 0.
struct mean_error {
  double mean = 0, error = 0;
};

inline mean_error ensemble_mean(const std::vector<double>& x) {
  mean_error r;
  if (x.empty()) return {std::nan(""), std::nan("")};
  for (double v : x) r.mean += v;
  r.mean /= static_cast<double>(x.size());
  if (x.size() < 2) return {r.mean, std::nan("")};
  double ss = 0;
  for (double v : x) ss += (v - r.mean) * (v - r.mean);
  r.error = std::sqrt(ss / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
  return r;
}

/// The largest distance between the empirical CDF of x and the standard normal's.
inline double normal_ks_distance(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double F = 0.5 * std::erfc(-x[i] / std::sqrt(2.0));
    d = std::max({d, F - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - F});
  }
  return d;
}

/// Kolmogorov's critical distance at level 0.001 for n samples (asymptotic: 1.949/√n).
inline double ks_critical_0_001(std::size_t n) { return 1.949 / std::sqrt(static_cast<double>(n)); }

}  // namespace rotlie::models
