#pragma once
// Writers for `rotlie solve`: JSON (shape of the CLI contract) and a ranked text table.
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

nlohmann::json solve_json(const solver::family_result& r, const lie::moments_of_inertia& body, const std::string& family,
                          int digits);
std::string solve_text(const solver::family_result& r, const lie::moments_of_inertia& body, int digits, std::size_t rows);

}  // namespace rotlie::runs
