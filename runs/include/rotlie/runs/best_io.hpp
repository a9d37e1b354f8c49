#pragma once
// The JSON of `rotlie best` (a contract: fields are added, never renamed).
#include <nlohmann/json.hpp>

#include "rotlie/runs/best_for_body.hpp"

namespace rotlie::runs {

/// {"inertia", "s", "t", "N": {…}, "R": {…}, "P": {…}, "reference", "recommended", "measure",
///  [measured fields], "cpu_seconds"}
nlohmann::ordered_json best_json(const runs::best_result& r);

}  // namespace rotlie::runs

// The Python module (python/src) still spells these rotlie::reports::…, where they lived before; the
// names stay reachable there until its call sites say runs::.
namespace rotlie::reports {
using runs::best_json;
}  // namespace rotlie::reports
