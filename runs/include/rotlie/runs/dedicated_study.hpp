#pragma once
// The solving behind the report's section "Dedicated N integrators": Tables 2 and 3 (spherical top) and
// Table 4 (water) by the solver, and the free-parameter families R and P for water (LV section 3.4).
// Plain results; reports/dedicated_section writes their JSON and formats them.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

/// Digits of every solution of the study.
inline constexpr int dedicated_study_digits = 40;

/// One free-parameter family for water.
struct dedicated_family {
  std::string name;  ///< "R" or "P"
  int paper = 0;     ///< the paper's count of real critical points
  solver::family_result result;
  double seconds = 0;  ///< wall time of the solving
};

struct dedicated_study_result {
  lie::moments_of_inertia sphere_body, water_body;
  solver::family_result sphere, water;  ///< N1-N7: sphere in ABC, water in every permutation
  double seconds = 0;                   ///< wall time of both
  std::vector<dedicated_family> families;  ///< R and P for water; empty with `quick`
};

/// Solves the N family for both bodies and, unless `quick`, R and P for water; `progress` receives a
/// line before each free-parameter family.
dedicated_study_result dedicated_study(bool quick, const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
