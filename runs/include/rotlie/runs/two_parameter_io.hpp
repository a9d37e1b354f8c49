#pragma once
// The JSON of `rotlie solve --family Q|QRS` (two free parameters).
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/solver/two_parameter.hpp"

namespace rotlie::runs {

/// {"family", "inertia", "digits", "starts", "cpu_seconds", "systems": [...]}, ranked as solved.
nlohmann::ordered_json two_parameter_json(const solver::two_parameter_result& result, const std::string& family,
                                          const lie::moments_of_inertia& body, int digits, int starts);

}  // namespace rotlie::runs
