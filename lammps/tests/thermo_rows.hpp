// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// The thermo rows LAMMPS prints to its screen: each block starts with a header line whose first word
// is Step and ends at "Loop time of"; a row is a line of numbers, one per column of the header.
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace rotlie_lammps_test {

struct thermo_block {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// The values of one column (empty when there is no such column).
  std::vector<double> column(const std::string& name) const {
    std::vector<double> out;
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == name)
        for (const auto& r : rows) out.push_back(r[c]);
    return out;
  }
};

inline std::vector<thermo_block> thermo_blocks(const std::string& output) {
  std::vector<thermo_block> blocks;
  std::istringstream in(output);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (w.empty()) continue;
    if (w[0] == "Step") {
      blocks.push_back({w, {}});
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.rfind("Loop time of", 0) == 0) {
      inside = false;
      continue;
    }
    if (w.size() != blocks.back().columns.size()) continue;  // a warning between the rows
    std::vector<double> row;
    for (const auto& x : w) {
      char* end = nullptr;
      const double v = std::strtod(x.c_str(), &end);
      if (end == x.c_str() || *end != '\0') break;
      row.push_back(v);
    }
    if (row.size() == w.size()) blocks.back().rows.push_back(row);
  }
  return blocks;
}

inline double mean(const std::vector<double>& x) {
  double s = 0;
  for (const double v : x) s += v;
  return x.empty() ? NAN : s / static_cast<double>(x.size());
}

/// The standard error of the mean of a correlated series by blocking (Flyvbjerg & Petersen 1989):
/// the series cut into `blocks` consecutive blocks, the spread of the block means.
inline double blocked_error(const std::vector<double>& x, std::size_t blocks = 10) {
  const std::size_t n = x.size() / blocks;
  if (n == 0) return NAN;
  std::vector<double> means;
  for (std::size_t b = 0; b < blocks; ++b) means.push_back(mean(std::vector<double>(x.begin() + static_cast<long>(b * n),
                                                                                    x.begin() + static_cast<long>((b + 1) * n))));
  const double m = mean(means);
  double s2 = 0;
  for (const double v : means) s2 += (v - m) * (v - m);
  return std::sqrt(s2 / static_cast<double>(blocks - 1) / static_cast<double>(blocks));
}

}  // namespace rotlie_lammps_test
