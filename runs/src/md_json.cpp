#include "rotlie/runs/md_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

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

constexpr double unstable_percent = 100;       // energy error ≥ the potential's own fluctuation
constexpr double round_off_units = 1000;       // a fluctuation below 1000 ε is round-off's
constexpr double round_off_per_step = 10;      // what a step's roundings (tens of stages) can add up to, in ε

// What `steps` steps' roundings can reach on quantities of size `unit`: 1000 units, or 10 a step.
double round_off_reach(double unit, long steps) {
  return std::max(round_off_units, round_off_per_step * static_cast<double>(std::max(1L, steps))) * unit;
}

void add_flags(nlohmann::json& j, const md_verdict& v) {
  j["unstable"] = v.unstable;
  j["round_off_floor"] = v.round_off_floor;
}

// {"every", "t_ps", "Q" (3×3 each), "G", "energy", "potential"} when a trajectory was asked for
void add_trajectory(nlohmann::json& j, const models::md_trajectory& tr) {
  if (tr.every <= 0) return;
  nlohmann::json Qs = nlohmann::json::array(), Gs = nlohmann::json::array();
  for (const auto& Q : tr.Q) Qs.push_back({{Q[0], Q[1], Q[2]}, {Q[3], Q[4], Q[5]}, {Q[6], Q[7], Q[8]}});
  for (const auto& G : tr.G) Gs.push_back({G[0], G[1], G[2]});
  j["trajectory"] = {{"every", tr.every}, {"t_ps", tr.t_ps}, {"Q", Qs}, {"G", Gs}, {"energy", tr.energy}, {"potential", tr.potential}};
}

std::string text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

std::string mean_error_text(double mean, double error) {
  return text(mean) + " ± " + (std::isnan(error) ? std::string("unknown (one run)") : text(error));
}

md_verdict verdict_of(const models::free_water_result& r) {
  md_verdict v;
  double largest = 0;
  for (double d : r.delta) largest = std::max(largest, d);
  // Round-off accumulates step by step: a δ that many steps' roundings could make (10 ε each; SIER4 at
  // h = 1e-50 fs grows δ to 6e-10 in 10⁶ steps, about 3 ε per step) measures round-off too.
  v.round_off_floor = largest < round_off_reach(r.round_off, r.steps);
  if (v.round_off_floor)
    v.warnings.push_back("delta stays below " + text(largest) + ", within what the scalar's round-off reaches in " +
                         std::to_string(r.steps) + " steps: tau measures round-off, not the integrator (an exact rotor has "
                         "no error here; try a larger step or --scalar float128)");
  else if (r.fitted_samples < 2)
    v.warnings.push_back(
        "fewer than two samples have 10 × reference error < delta <= 0.1: tau is not defined "
        "(run longer if delta is at round-off, shorter if it has saturated)");
  return v;
}

md_verdict verdict_of(const models::dipole_field_result& r) {
  md_verdict v;
  const long runs = static_cast<long>(r.dH_over_dV_percent.size()) + r.failed_runs + r.undefined_runs;
  if (r.failed_runs > 0)
    v.warnings.push_back(std::to_string(r.failed_runs) + " of " + std::to_string(runs) +
                         " runs diverged (non-finite energy) and are left out of the means");
  if (r.undefined_runs > 0)
    v.warnings.push_back(std::to_string(r.undefined_runs) + " of " + std::to_string(runs) +
                         " runs have no finite dH/dV (V did not fluctuate, or the energies' squares are beyond the scalar's range) "
                         "and are left out of the means");
  v.round_off_floor = r.turn_per_step < round_off_units;
  if (v.round_off_floor)
    v.warnings.push_back("one step turns the molecule by " + text(r.turn_per_step) +
                         " ε only: the step's change is lost in round-off and dH/dV measures round-off, not the integrator "
                         "(take a larger step or a wider --scalar)");
  v.unstable = !v.round_off_floor && r.dH.mean >= unstable_percent;
  if (v.unstable)
    v.warnings.push_back("dH/dV = " + text(r.dH.mean) + " % >= 100 %: the energy error is as large as the potential's own "
                         "fluctuation; the step is beyond the integrator's stable range");
  return v;
}

md_verdict verdict_of(const models::liquid_water_run_result& r) {
  md_verdict v;
  // a run's dE within what double's round-off reaches on its energies (a state far too hot) measures round-off
  int lost = 0;
  double smallest = 0, reach = 0;
  const long steps_per_run = r.runs > 0 ? r.steps / r.runs : r.steps;
  for (std::size_t k = 0; k < r.dE.size(); ++k) {
    const double floor = round_off_reach(std::numeric_limits<double>::epsilon() * r.energy_size[k], steps_per_run);
    if (r.dE[k] < floor && (lost++ == 0 || r.dE[k] < smallest)) smallest = r.dE[k], reach = floor;
  }
  v.round_off_floor = lost > 0;
  if (v.round_off_floor)
    v.warnings.push_back(std::to_string(lost) + " of " + std::to_string(r.runs) + " runs have dE = " + text(smallest) +
                         " kcal/mol, within what double's round-off reaches on energies of their size (" + text(reach) +
                         "): dE/dV measures round-off, not the integrator (is the state far too hot? its temperature is " +
                         text(r.temperature) + " K)");
  v.unstable = !v.round_off_floor && r.ratio_mean >= unstable_percent;
  if (v.unstable)
    v.warnings.push_back("dE/dV = " + text(r.ratio_mean) + " % >= 100 %: the energy error is as large as the potential's own "
                         "fluctuation; the step is beyond the integrator's stable range");
  return v;
}

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
  add_flags(j, verdict_of(r));
  add_trajectory(j, r.trajectory);
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
  j["undefined_runs"] = r.undefined_runs;
  j["cpu_s_per_ps"] = r.cpu_s_per_ps;
  add_flags(j, verdict_of(r));
  add_trajectory(j, r.trajectory);
  return j;
}

nlohmann::json liquid_water_json(const models::liquid_water_run_result& r) {
  auto j = nlohmann::json{{"scene", "liquid-water"},
                        {"integrator", r.integrator},
                        {"h_fs", r.h_fs},
                        {"f", r.f},
                        {"runs", r.runs},
                        {"molecules", r.molecules},
                        {"dE_over_dV_percent", {number_or_null(r.ratio_mean), number_or_null(r.ratio_error)}},
                        {"potential_kcal_per_mol", r.potential_per_molecule},
                        {"temperature_K", r.temperature},
                        {"ms_per_step", r.ms_per_step},
                        {"cpu_ms_per_step", r.cpu_ms_per_step},
                        {"momentum_drift", r.momentum_drift}};
  add_flags(j, verdict_of(r));
  add_trajectory(j, r.trajectory);
  return j;
}

nlohmann::json liquid_water_nvt_json(const models::liquid_water_nvt_result& r) {
  return nlohmann::json{{"scene", "liquid-water"},
                        {"ensemble", "NVT"},
                        {"integrator", r.integrator},
                        {"table", r.table},
                        {"h_fs", r.h_fs},
                        {"f", r.f},
                        {"molecules", r.molecules},
                        {"steps", r.steps},
                        {"measured_steps", r.measured_steps},
                        {"target_K", r.kelvin},
                        {"translational_K", pair_json(r.translational_K)},
                        {"rotational_K", pair_json(r.rotational_K)},
                        {"translational_after_o_K", pair_json(r.translational_after_o_K)},
                        {"rotational_after_o_K", pair_json(r.rotational_after_o_K)},
                        {"configurational_translational_K", pair_json(r.configurational_translational_K)},
                        {"configurational_rotational_K", pair_json(r.configurational_rotational_K)},
                        {"potential_kcal_per_mol", pair_json(r.potential_per_molecule)},
                        {"rdf_first_peak", {{"r_A", r.rdf_peak_r}, {"g", r.rdf_peak_g}}},
                        {"diffusion_1e-5_cm2_per_s", number_or_null(r.diffusion)},
                        {"extended_energy_drift_kcal_per_mol", r.extended_drift},
                        {"ms_per_step", r.ms_per_step},
                        {"cpu_ms_per_step", r.cpu_ms_per_step}};
}

}  // namespace rotlie::runs
