#pragma once
// The JSON of each md scene (`rotlie md --json`, rotlie.md from Python): one writer per scene's result;
// a contract: fields are added, never renamed.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "rotlie/models/scenes/liquid_water_experiment.hpp"
#include "rotlie/models/scenes/liquid_water_nvt.hpp"

namespace rotlie::runs {

/// What the numbers of a run mean, beyond the numbers: flags for the JSON ("unstable",
/// "round_off_floor") and one warning line each for a reader.
struct md_verdict {
  bool unstable = false;         ///< the energy error is as large as the potential's own fluctuation (≥ 100 %)
  bool round_off_floor = false;  ///< the measured error is within 1000 ε, or within 10 ε per step taken: it measures the scalar
  std::vector<std::string> warnings;
};
md_verdict verdict_of(const models::free_water_result& r);
md_verdict verdict_of(const models::dipole_field_result& r);
md_verdict verdict_of(const models::liquid_water_run_result& r);

/// "m ± e", or "m ± unknown (one run)" where the error is not a number.
std::string mean_error_text(double mean, double error);

/// What was run, as every md JSON starts: scene, integrator, step, length, runs, seed, scalar.
struct md_run_header {
  std::string scene, integrator, scalar;
  double h_fs = 0, T_ps = 0;
  long runs = 0;
  std::uint64_t seed = 0;
};

/// Each scene's JSON also has "trajectory" when one was asked for (--every K): {"every", "t_ps", "Q" (body 0's
/// attitude, 3×3), "G" (its body-frame angular momentum), "energy", "potential"}, every K steps from the start
/// (the ensembles' first run; liquid water's runs one after another, molecule 0).

/// {header…, "tau_ps", "tau_error_ps", "fitted_samples", "cpu_s_per_ps", "samples": [{"t_ps", "delta", "reference_delta"}],
/// "unstable", "round_off_floor"}; an error that is unknown (one run) is null
nlohmann::json free_water_json(const md_run_header& h, const models::free_water_result& r);

/// {header…, "dipole_debye", "field_MV_per_m", "dH_over_dV_percent": [mean, error], "dLz_over_Lz", "failed_runs",
/// "undefined_runs", "cpu_s_per_ps", "unstable", "round_off_floor"}
nlohmann::json dipole_field_json(const md_run_header& h, const models::dipole_field_result& r, double dipole_debye,
                                 double field_MV_per_m);

/// {"scene": "liquid-water", "integrator", "h_fs", "f", "runs", "molecules", "dE_over_dV_percent", …}
nlohmann::json liquid_water_json(const models::liquid_water_run_result& r);

/// liquid-water at a temperature (an integrator with -BAOAB, -OBABO, -NHC): "ensemble": "NVT", the
/// temperatures, V per molecule, g_OO's first peak, D; each measured value as [mean, standard error].
nlohmann::json liquid_water_nvt_json(const models::liquid_water_nvt_result& r);

}  // namespace rotlie::runs
