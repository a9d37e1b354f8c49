#pragma once
// The JSON of `rotlie binary` (a contract: fields are added, never renamed), its trajectory lines and
// its human summary; the reader of a start state is binary_state_file.hpp.
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/models/scenes/binary_system.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_state_file.hpp"

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


}  // namespace rotlie::runs
