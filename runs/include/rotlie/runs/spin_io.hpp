#pragma once
// The JSON of `rotlie spin` (a contract: fields are added, never renamed) and its human summary.
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

/// {"body", "moments", "e", "integrator", "scalar", "h", "T", "steps", "evaluations", "Q" (3 rows; columns the
/// body axes A, B, C in the inertial frame), "omega_body" (units of n), "theta", "energy_start", "energy_end", "cpu_s"}
nlohmann::json spin_json(const runs::spin_result& r);

/// The summary `rotlie spin` prints without --json: the run, the final Q, ω, θ, the energy and the
/// conserved quantity's check, the CPU time.
std::string spin_text(const runs::spin_result& r);

}  // namespace rotlie::runs
