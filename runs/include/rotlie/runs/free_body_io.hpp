#pragma once
// The JSON of `rotlie integrate`, `order` and `exact` (one writer per kind of result).
#include <nlohmann/json.hpp>

#include "rotlie/runs/free_body_runs.hpp"

namespace rotlie::runs {

/// {"scheme", "slope": null, "points": [{"h", "h_over_C", "error", "cpu_s", "reference_error"}]}
nlohmann::json integrate_json(const runs::integrate_result& r);

/// {"scheme", "scalar", "declared_order", "points": [...], "slope"} (slope null when not fitted)
nlohmann::json order_json(const runs::order_result& r);

/// {"T", "G": [3], "Q": [[3] × 3], "error_estimate"}
nlohmann::json exact_json(const runs::exact_result& r);

}  // namespace rotlie::runs
