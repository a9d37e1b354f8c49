#pragma once
// A mean and its standard error from block (or run) averages: the blocks taken as independent.
#include <cmath>
#include <vector>

namespace rotlie::models {

struct mean_and_error {
  double mean = 0, error = 0;  ///< error NaN for one block (unknown, not 0)
};

inline mean_and_error block_average(const std::vector<double>& blocks) {
  mean_and_error m;
  for (double b : blocks) m.mean += b / static_cast<double>(blocks.size());
  double var = 0;
  for (double b : blocks) var += (b - m.mean) * (b - m.mean);
  const double n = static_cast<double>(blocks.size());
  m.error = n > 1 ? std::sqrt(var / (n - 1) / n) : std::nan("");
  return m;
}

}  // namespace rotlie::models
