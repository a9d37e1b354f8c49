#pragma once
// The measurements of the report's section "Beyond the paper": dedicated 6th-order schemes for water
// (H_R3 = H_R5 = 0) found by Newton from random starts on 21-stage ABC palindromes, polished, their
// float128 slopes; isolated solutions for the spherical top; and the accuracy curves of the found
// schemes, of the general 6th-order compositions and of the 4th-order champions, with timed steps.
// Plain numbers; reports/beyond_section formats and draws them.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/sixth_order_scan.hpp"

namespace rotlie::runs {

/// The study's fixed sizes: starts per system (default, --full), tables kept, digits of a polished root.
inline constexpr int sixth_order_default_starts = 200, sixth_order_full_starts = 40, sixth_order_tables_shown = 3,
                     sixth_order_digits = 45;

/// A dedicated 6th-order table found for water.
struct sixth_order_found {
  schemes::scheme_table table;
  int cost = 0;      ///< rotations per step
  std::string text;  ///< the table as written
  std::string file;  ///< its file name in the report folder
  double remainder7 = 0, residual = 0, slope_water = 0, slope_other = 0;  ///< slopes in float128; other = (1/2, 4/5, 1)
  int hits = 0;
};

/// One root of the spherical top's search: polished (with slopes) or not (with the reason).
struct sixth_order_sphere_root {
  std::string word;
  double remainder7 = 0, condition = 0;  ///< ‖H_R7‖, σmin/σmax of the scaled Jacobian at the root
  bool polished = false;
  std::string failure;
  double residual = 0, slope_sphere = 0, slope_water = 0;
};

/// A general 6th-order composition at its best permutation for water.
struct sixth_order_general {
  double remainder7 = 0;  ///< NaN where the word is beyond the remainder engine's length
  double quad_slope = 0;  ///< float128
};

struct sixth_order_study_result {
  std::size_t remainder_word_limit = 0;  ///< longest word whose ‖H_R7‖ the remainder engine computes
  bool full = false;
  int starts = 0;                                ///< per system
  std::vector<solver::scanned_system> systems;   ///< the search
  solver::hit_statistics statistics;             ///< of the search's roots
  double search_seconds = 0;                     ///< its CPU time
  std::vector<sixth_order_found> found;          ///< best ‖H_R7‖ first
  std::vector<std::string> skipped;              ///< roots not polished: "WORD:PERM (reason)"
  std::vector<sixth_order_sphere_root> sphere;
  std::vector<scheme_curve> dedicated6, general6, fourth;  ///< protocol curves with timed steps
  std::vector<sixth_order_general> general;      ///< per general6 curve
  double seconds = 0;                            ///< the study's CPU time
};

/// Runs the study for water; `full` scans every 21-stage palindrome, `quick` uses a quarter of the starts.
sixth_order_study_result sixth_order_study(bool quick, bool full, const std::function<void(const std::string&)>& progress = {});

/// CPU seconds per unit of simulated time a curve needs for a mean attitude error e, from its fitted
/// law e = K (h/C)^p and cpu = t_step / h.
double cpu_for_error(const scheme_curve& c, double e);
/// The error a curve reaches with `cpu` seconds per unit time.
double error_at_cpu(const scheme_curve& c, double cpu);

}  // namespace rotlie::runs
