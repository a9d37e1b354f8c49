#pragma once
// The measurements behind the claims of LV sections 4 and 5 that the report's audit computes through the
// library (the other claims read the files of earlier sections): the costs of the tables, CPU time per
// rotation, the moments of water and of Fassò's body, the RS parts for the sphere, the small-angle form
// of the attitude error, SR schemes against RS, the body grid, and the numerically best R and P for water.
// Plain numbers; reports/audit_section compares them with the paper.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotlie::runs {

/// A number measured for a scheme, and the scheme's name: sorted, the smallest number first (then the name).
using measured_value = std::pair<double, std::string>;

/// Among the P of smallest ‖H_R5‖ (from the dedicated section's solutions_water_P.json), the measured ones.
struct lv_audit_best_p {
  std::vector<measured_value> measured;  ///< error/(h/C)^4 and name, smallest first
  measured_value favourite;              ///< the smallest ‖H_R5‖'s constant and name
  double p1_constant = 0;             ///< P1 BAC (5)'s error/(h/C)^4
  std::size_t p1_rank = 0;            ///< its rank by ‖H_R5‖, from 1
  std::size_t solutions = 0;          ///< P solutions in the file
};

struct lv_audit_options {
  bool quick = false;
  /// solutions_water_P.json of the dedicated section; empty when that section did not run
  std::filesystem::path solutions_water_P;
};

struct lv_audit_study_result {
  int cost_mclachlan = 0, cost_n2 = 0, cost_p1 = 0, cost_r4 = 0;  ///< rotations per step
  std::vector<std::pair<std::string, double>> seconds_per_rotation;  ///< N2 BAC (2), R ABC (4), P1 BAC (5), RS4-S5-McLachlan:CBA
  std::string fasso_rejection;                    ///< why (0.345, 0.653, 1) is refused; empty when accepted
  double water_I1 = 0, water_I2 = 0;
  bool sphere_r_zero = false, sphere_s_nonzero = false;  ///< the RS parts at I = (1, 1, 1)
  double small_angle_worst = 0;  ///< largest relative difference of R^9 error and √3 × rms angle
  std::string sr_equal_at;       ///< permutations where RSRSRSR's remainder equals SRSRSRS's, ", "-joined
  std::size_t grid_points = 0, grid_asymmetric = 0;  ///< --grid 200
  std::vector<measured_value> r_measured;  ///< every R for water: error/(h/C)^4, smallest first
  std::size_t r_solutions = 0;
  std::size_t r_abc4_rank = 0;          ///< R ABC (4)'s rank by ‖H_R5‖, from 1
  std::optional<lv_audit_best_p> best_p;
  std::string best_p_missing;           ///< why best_p is absent
  double cpu_seconds = 0;               ///< the study's CPU time
};

lv_audit_study_result lv_audit_study(const lv_audit_options& options);

}  // namespace rotlie::runs
