#pragma once
// The JSON of `rotlie best` (a contract: fields are added, never renamed).
#include <nlohmann/json.hpp>

#include "rotlie/runs/best_for_body.hpp"

namespace rotlie::runs {

/// {"inertia", "s", "t", "N": {…}, "R": {…}, "P": {…}, "reference", "recommended", "measure",
///  [measured fields], "cpu_seconds"}
nlohmann::ordered_json best_json(const runs::best_result& r);

}  // namespace rotlie::runs
