#pragma once
// The JSON of each md scene (`rotlie md --json`, rotlie.md from Python): one writer per scene's result;
// a contract: fields are added, never renamed.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "rotlie/models/scenes/liquid_water_experiment.hpp"

namespace rotlie::runs {

/// What was run, as every md JSON starts: scene, integrator, step, length, runs, seed, scalar.
struct md_run_header {
  std::string scene, integrator, scalar;
  double h_fs = 0, T_ps = 0;
  long runs = 0;
  std::uint64_t seed = 0;
};

/// {header…, "tau_ps", "tau_error_ps", "fitted_samples", "cpu_s_per_ps", "samples": [{"t_ps", "delta", "reference_delta"}]}
nlohmann::json free_water_json(const md_run_header& h, const models::free_water_result& r);

/// {header…, "dipole_debye", "field_MV_per_m", "dH_over_dV_percent": [mean, error], "dLz_over_Lz", "failed_runs", "cpu_s_per_ps"}
nlohmann::json dipole_field_json(const md_run_header& h, const models::dipole_field_result& r, double dipole_debye,
                                 double field_MV_per_m);

/// {"scene": "liquid-water", "integrator", "h_fs", "f", "runs", "molecules", "dE_over_dV_percent", …}
nlohmann::json liquid_water_json(const models::liquid_water_run_result& r);

}  // namespace rotlie::runs
