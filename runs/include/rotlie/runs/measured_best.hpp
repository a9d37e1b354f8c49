#pragma once
// The measured column of `rotlie best` (issue 14, item 7): the numeric protocol of LV section 4.1
// (G(0) = (1, 1, 1), identity attitude, T = 1, mean R^9 attitude distance over every step) at ONE
// fixed reduced step h/C = 1/1980, in double, against the exact motion in long double. 1980 is a
// multiple of 9, 10, 11 and 12, so N, R, P and RS4 S5 McLachlan all take a whole number of steps
// (220, 198, 180, 165) to T = 1; a scheme whose cost does not divide 1980 takes round(1980/C)
// steps and its error is brought to h/C = 1/1980 by (h/C ratio)^order, its asymptotic law.
#include <map>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

inline constexpr int measured_best_steps_per_cost = 1980;  ///< 1 / (h/C)

class fixed_reduced_step_protocol {
 public:
  explicit fixed_reduced_step_protocol(const lie::moments_of_inertia& body);
  /// The mean attitude error at h/C = 1/1980 (see above).
  double error(const schemes::scheme_table& table) const;

 private:
  std::string inertia_;
  mutable std::map<long, std::vector<std::array<double, 9>>> exact_;  ///< exact attitudes at t = k/n, by n
  const std::vector<std::array<double, 9>>& exact_attitudes(long n) const;
};

struct measured_reference {
  std::string name;  ///< BASE:PERM at the base's best measured permutation
  int cost = 0, order = 0;
  double error = 0;
};

/// Every reference scheme (schemes::reference_scheme_names) at its best measured permutation.
std::vector<measured_reference> measure_references(const fixed_reduced_step_protocol& protocol);

}  // namespace rotlie::runs
