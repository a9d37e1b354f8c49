#pragma once
// The measurements of the report's section "Stability: where methods fail": for water, a near-symmetric
// and a near-flat body, the step beyond which each scheme stops working (models/stability_scan.hpp).
// Plain numbers; reports/stability_section formats and draws them.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/models/stability_scan.hpp"

namespace rotlie::runs {

/// One scheme's scan.
struct stability_row {
  std::string name;
  int cost = 0;  ///< C/C0
  models::stability_scan_result scan;
};

/// One body: its key (file names), title, moments as text, and every scheme's scan.
struct stability_body {
  std::string key, title, inertia;
  std::vector<stability_row> rows;
};

struct stability_study_result {
  double threshold = 0.1;  ///< mean attitude error (or relative energy error) that counts as failure
  double total_time = 0;   ///< T of every run
  std::vector<stability_body> bodies;
};

/// Runs the study (T = 4 with `quick`, else 10); `progress` receives each body's title.
stability_study_result stability_study(bool quick, const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
