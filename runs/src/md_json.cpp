#include "rotlie/runs/md_json.hpp"

#include <cmath>

namespace rotlie::runs {
namespace {

nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json pair_json(const models::mean_error& m) { return {number_or_null(m.mean), number_or_null(m.error)}; }

// The fields every scene's JSON has: what was run, with which step, cost and seed.
nlohmann::json run_json(const md_run_header& h, int f, long steps) {
  return {{"scene", h.scene}, {"integrator", h.integrator}, {"h_fs", h.h_fs}, {"f", f},
          {"h_over_f_fs", h.h_fs / f}, {"T_ps", h.T_ps}, {"steps", steps}, {"runs", h.runs},
          {"seed", h.seed}, {"scalar", h.scalar}};
}

}  // namespace

nlohmann::json free_water_json(const md_run_header& h, const models::free_water_result& r) {
  nlohmann::json samples = nlohmann::json::array();
  for (std::size_t j = 0; j < r.t_ps.size(); ++j)
    samples.push_back({{"t_ps", r.t_ps[j]}, {"delta", r.delta[j]}, {"reference_delta", r.reference_delta[j]}});
  auto j = run_json(h, r.f, r.steps);
  j["tau_ps"] = number_or_null(r.tau_ps);
  j["tau_error_ps"] = number_or_null(r.tau_error_ps);
  j["fitted_samples"] = r.fitted_samples;
  j["cpu_s_per_ps"] = r.cpu_s_per_ps;
  j["samples"] = samples;
  return j;
}

nlohmann::json dipole_field_json(const md_run_header& h, const models::dipole_field_result& r, double dipole_debye,
                                 double field_MV_per_m) {
  auto j = run_json(h, r.f, r.steps);
  j["dipole_debye"] = dipole_debye;
  j["field_MV_per_m"] = field_MV_per_m;
  j["dH_over_dV_percent"] = pair_json(r.dH);
  j["dLz_over_Lz"] = pair_json(r.dLz);
  j["failed_runs"] = r.failed_runs;
  j["cpu_s_per_ps"] = r.cpu_s_per_ps;
  return j;
}

nlohmann::json liquid_water_json(const models::liquid_water_run_result& r) {
  return nlohmann::json{{"scene", "liquid-water"},
                        {"integrator", r.integrator},
                        {"h_fs", r.h_fs},
                        {"f", r.f},
                        {"runs", r.runs},
                        {"molecules", r.molecules},
                        {"dE_over_dV_percent", {r.ratio_mean, r.ratio_error}},
                        {"potential_kcal_per_mol", r.potential_per_molecule},
                        {"temperature_K", r.temperature},
                        {"ms_per_step", r.ms_per_step},
                        {"cpu_ms_per_step", r.cpu_ms_per_step},
                        {"momentum_drift", r.momentum_drift}};
}

}  // namespace rotlie::runs
