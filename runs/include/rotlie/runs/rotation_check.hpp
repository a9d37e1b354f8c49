#pragma once
// Whether a 3×3 matrix a user gave is a rotation, and if not why, in numbers that are finite and true:
// |QᵀQ − 1| (the largest entry) and det Q are shown only while they cannot overflow (entries up to
// 1e100); beyond that the entry itself is named.
#include <algorithm>
#include <cmath>
#include <string>

#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

/// Why the row-major 3×3 matrix q is not a proper rotation to within `tolerance` on |QᵀQ − 1|, or "".
inline std::string rotation_problem(const double* q, double tolerance) {
  using schemes::message_number;
  const auto entry = [&](int i, int k) { return q[3 * i + k]; };
  const auto place = [](int i, int k) { return "[" + std::to_string(i) + "][" + std::to_string(k) + "]"; };
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(entry(i, k))) return "its entry " + place(i, k) + " is not finite";
      if (std::abs(entry(i, k)) > 1e100) return "its entry " + place(i, k) + " = " + message_number(entry(i, k)) + " lies outside [-1, 1]";
    }
  double gap = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      double p = i == k ? -1.0 : 0.0;
      for (int m = 0; m < 3; ++m) p += entry(m, i) * entry(m, k);
      gap = std::max(gap, std::abs(p));
    }
  const double det = entry(0, 0) * (entry(1, 1) * entry(2, 2) - entry(1, 2) * entry(2, 1)) - entry(0, 1) * (entry(1, 0) * entry(2, 2) - entry(1, 2) * entry(2, 0)) +
                     entry(0, 2) * (entry(1, 0) * entry(2, 1) - entry(1, 1) * entry(2, 0)) + 0.0;  // + 0: never "-0"
  if (gap <= tolerance && det > 0) return "";
  return "|QᵀQ − 1| = " + message_number(gap) + ", det " + message_number(det) + (gap <= tolerance ? ": a reflection" : "");
}

}  // namespace rotlie::runs
