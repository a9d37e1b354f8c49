#pragma once
// The JSON of `rotlie sixth` (the 6th-order search for one body, and --references).
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/runs/sixth_search.hpp"

namespace rotlie::runs {

/// {"inertia", "split", "systems", … hit statistics …, "cpu_seconds", "best": [tables]}
nlohmann::ordered_json sixth_json(const runs::sixth_search_result& r, const lie::moments_of_inertia& body,
                                  const std::string& split);

/// The general 6th-order compositions: [{"name", "order", "stages", "cost", "source"}]
nlohmann::ordered_json sixth_references_json();

}  // namespace rotlie::runs
