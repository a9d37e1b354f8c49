// free-water: one water molecule without forces, vZS section V.A: the orientation error time τ of an
// integrator against the exact motion (eq. (52)), in double, long double or float128.
#include <sstream>

#include "ensemble_run.hpp"
#include "held_ensemble.hpp"
#include "../md_experiments.hpp"
#include "rotlie/models/experiments/free_water_nvt.hpp"

namespace rotlie::runs {
namespace {

using namespace scene_support;

template <class T>
scene_result run_in(const ensemble_run& e) {
  const auto result = models::run_free_water(models::free_water<T>{}, e.run);
  if (!result.finite)
    throw std::runtime_error("the integration diverged (non-finite attitude): the step is beyond the integrator's stability limit");
  std::ostringstream text;
  text << run_summary(e, "free water", result.f, result.steps) << "  tau = " << mean_error_text(result.tau_ps, result.tau_error_ps)
       << " ps (delta = t/(10 tau) fitted over " << result.fitted_samples << " of " << result.t_ps.size()
       << " samples)\n  delta(T) = " << result.delta.back() << " (exact reference: " << result.reference_delta.back()
       << ")\n  CPU " << result.cpu_s_per_ps << " s per simulated ps\n";
  return {free_water_json(e.header(), result), text.str(), verdict_of(result).warnings};
}

// At a temperature: the runs' temperatures and the Maxwell-Boltzmann test (free_water_nvt.hpp).
scene_result run_at_temperature(const ensemble_run& e, const thermostat_request& t) {
  if (e.scalar != "double") throw bad_input("--scalar " + e.scalar + ": a thermostat draws its noise in double");
  if (e.run.runs < 20) throw bad_input("--runs must be at least 20 at a temperature (the Maxwell-Boltzmann test takes every run's end)");
  if (e.run.every > 0) throw bad_input("--every: no trajectory is kept at a temperature");
  const auto r = as_bad_input([&] { return models::run_free_water_nvt(e.run, t.kelvin, t.friction_per_ps / 1000, t.tau_ps * 1000); });
  nlohmann::json j = {{"scene", "free-water"},        {"ensemble", "NVT"},
                      {"integrator", e.run.integrator.name}, {"table", r.table},
                      {"h_fs", e.run.h_fs},            {"T_ps", e.run.T_ps},
                      {"runs", e.run.runs},            {"steps", r.steps},
                      {"seed", e.run.seed},            {"target_K", r.kelvin},
                      {"translational_K", {r.translational_K.mean, r.translational_K.error}},
                      {"rotational_K", {r.rotational_K.mean, r.rotational_K.error}},
                      {"ks_translational", r.ks_translational},
                      {"ks_rotational", r.ks_rotational},
                      {"ks_critical_0_001", r.ks_critical},
                      {"maxwell_boltzmann", r.ks_translational < r.ks_critical && r.ks_rotational < r.ks_critical},
                      {"cpu_s_per_ps", r.cpu_s_per_ps},
                      {"unstable", false},  // a run that diverges stops with an error; the flags every md result carries
                      {"round_off_floor", false}};
  std::ostringstream text;
  text << "free water at " << r.kelvin << " K, " << e.run.integrator.name << " (" << r.table << "), h = " << e.run.h_fs << " fs, " << e.run.runs
       << " runs of " << r.steps << " steps (the first fifth settling), seed " << e.run.seed << "\n"
       << "  T translational  " << r.translational_K.mean << " ± " << r.translational_K.error << " K\n"
       << "  T rotational     " << r.rotational_K.mean << " ± " << r.rotational_K.error << " K\n"
       << "  Kolmogorov-Smirnov distance of the runs' ends from Maxwell-Boltzmann: " << r.ks_translational << " (p), " << r.ks_rotational
       << " (G); critical at 0.001: " << r.ks_critical << "\n";
  scene_result out{j, text.str(), {}};
  if (!j["maxwell_boltzmann"].get<bool>())
    out.warnings.push_back("the runs' ends are not Maxwell-Boltzmann distributed (Kolmogorov-Smirnov at 0.001): too short a run to settle "
                           "(a few --friction or --tau times), or chains that do not mix one free molecule's momenta");
  return out;
}

scene_result free_water_scene_run(const scene_request& r) {
  ensemble_run e;
  read_ensemble_run(r, models::water::body_text(), e, true);
  if (const auto t = read_thermostat(r, e.run.integrator)) return run_at_temperature(e, *t);
  return in_scalar(e, [&e](auto zero) { return run_in<decltype(zero)>(e); });
}

// The ensemble held (md_simulation): its runs' states from the same checked options.
std::unique_ptr<held_md_run> free_water_scene_hold(const scene_request& r) {
  ensemble_run e;
  read_ensemble_run(r, models::water::body_text(), e);  // a thermostat refused: a held run is at constant energy
  return as_bad_input([&] {
    auto held = in_held_scalar(e, [&e](auto zero) { return held_ensemble(models::free_water<decltype(zero)>{}, e.run, false); });
    held->setup = held_setup_of(e);
    return held;
  });
}

std::vector<scene_option> free_water_options() {
  auto o = ensemble_options(models::free_water_default_T_ps, models::free_water_default_runs);
  o.insert(o.end(), {thermostat_option_temperature(), thermostat_option_friction(), thermostat_option_tau()});
  return o;
}

}  // namespace

scene free_water_scene() {
  return {"free-water", "one free water molecule: the orientation error time tau (vZS section V.A)",
          free_water_options(), free_water_scene_run,
          free_water_scene_hold};
}

}  // namespace rotlie::runs
