#pragma once
// The start of a binary run from JSON (`--state FILE`, a sweep's inline "state"), declared apart from
// the JSON writer so that the run itself does not parse nlohmann/json (binary_io.cpp defines these).
#include <string>

#include "rotlie/models/scenes/binary_system.hpp"

namespace rotlie::runs {

/// A start from a JSON file with "r", "v" (km, km/s), "Q1", "Q2" (3×3, rows; proper rotations to 1e-9,
/// then made orthogonal to round-off) and "omega1", "omega2" (rad/s, body frames): the fields of
/// binary_json, so a run's output starts the next. Each component of r, v and the omegas at most 1e30
/// in size, |r| at least 1e-30 km. Throws bad_input naming --state and the field.
models::binary_state<double> read_binary_state(const std::string& path, const models::binary_system<double>& sys);

/// The same from the JSON text; `where` names it in messages.
models::binary_state<double> parse_binary_state(const std::string& text, const std::string& where, const models::binary_system<double>& sys);

}  // namespace rotlie::runs
