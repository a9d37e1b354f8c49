#pragma once
// The JSON of `rotlie binary` (a contract: fields are added, never renamed), its trajectory lines,
// its human summary, and the reader of a start state (--state FILE).
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/models/scenes/binary_system.hpp"
#include "rotlie/runs/binary_run.hpp"

namespace rotlie::runs {

/// {"system", "primary", "secondary", "order", "G", "integrator", "h", "T", "steps", "evaluations", "masses",
///  "moments", "densities", "t", "r", "v", "Q1", "Q2" (row by row; columns the body axes in the inertial
///  frame), "omega1", "omega2" (rad/s, body frames), "energy", "energy_start", "angular_momentum",
///  "max_rel_energy_error", "max_rel_angular_momentum_error", "cpu_s", "mutual": {"U", "F" (on body 2),
///  "M1", "M2" (about each body's centre, inertial)}, "unstable", "round_off_floor", "warnings"}.
/// Units km, kg, s (energies in kg km² s⁻²).
nlohmann::json binary_json(const binary_result& r);

/// One trajectory sample: {"t", "r", "v", "Q1", "Q2", "omega1", "omega2", "energy"}.
nlohmann::json binary_sample_json(const binary_sample& s, const models::binary_system<double>& sys);

/// The summary `rotlie binary` prints without --json.
std::string binary_text(const binary_result& r);

/// A start from a JSON file with "r", "v" (km, km/s), "Q1", "Q2" (3×3, rows; proper rotations to 1e-9,
/// then made orthogonal to round-off) and "omega1", "omega2" (rad/s, body frames): the fields of
/// binary_json, so a run's output starts the next. Throws bad_input naming --state.
models::binary_state<double> read_binary_state(const std::string& path, const models::binary_system<double>& sys);

/// The same from the JSON text; `where` names it in messages.
models::binary_state<double> parse_binary_state(const std::string& text, const std::string& where, const models::binary_system<double>& sys);

}  // namespace rotlie::runs
