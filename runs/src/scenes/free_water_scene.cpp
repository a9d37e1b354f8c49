// free-water: one water molecule without forces, vZS section V.A: the orientation error time τ of an
// integrator against the exact motion (eq. (52)), in double, long double or float128.
#include <sstream>

#include "ensemble_run.hpp"
#include "held_ensemble.hpp"
#include "../md_experiments.hpp"

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

scene_result free_water_scene_run(const scene_request& r) {
  ensemble_run e;
  read_ensemble_run(r, models::water::body_text(), e);
  return in_scalar(e, [&e](auto zero) { return run_in<decltype(zero)>(e); });
}

// The ensemble held (md_simulation): its runs' states from the same checked options.
std::unique_ptr<held_md_run> free_water_scene_hold(const scene_request& r) {
  ensemble_run e;
  read_ensemble_run(r, models::water::body_text(), e);
  return as_bad_input([&] {
    auto held = in_held_scalar(e, [&e](auto zero) { return held_ensemble(models::free_water<decltype(zero)>{}, e.run, false); });
    held->setup = held_setup_of(e);
    return held;
  });
}

}  // namespace

scene free_water_scene() {
  return {"free-water", "one free water molecule: the orientation error time tau (vZS section V.A)",
          ensemble_options(models::free_water_default_T_ps, models::free_water_default_runs), free_water_scene_run,
          free_water_scene_hold};
}

}  // namespace rotlie::runs
