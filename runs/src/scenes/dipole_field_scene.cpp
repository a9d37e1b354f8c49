// dipole-field: a water molecule's dipole in a constant field, vZS section V.B (Table I): the energy
// fluctuation ΔH/ΔV and ΔL_z/⟨L_z⟩ of an integrator over an ensemble.
#include <sstream>

#include "ensemble_run.hpp"
#include "held_ensemble.hpp"
#include "../md_experiments.hpp"

namespace rotlie::runs {
namespace {

using namespace scene_support;

struct dipole_run : ensemble_run {
  std::string dipole, field;  ///< shortest decimals, read alike by every scalar
};

template <class T>
scene_result run_in(const dipole_run& e) {
  const auto result = models::run_dipole_field(models::dipole_field<T>(e.dipole, e.field), e.run);
  if (result.failed_runs == e.run.runs)
    throw std::runtime_error("every run diverged (non-finite energy): the step is beyond the integrator's stability limit");
  if (result.dH_over_dV_percent.empty())
    throw std::runtime_error("no run has a finite dH/dV (" + std::to_string(result.failed_runs) + " diverged, " +
                             std::to_string(result.undefined_runs) +
                             " with V not fluctuating or the energies' squares beyond the scalar's range)");
  std::ostringstream text;
  text << run_summary(e, "dipole in a field", result.f, result.steps) << "  dH/dV = " << mean_error_text(result.dH.mean, result.dH.error)
       << " %\n  dLz/<Lz> = " << mean_error_text(result.dLz.mean, result.dLz.error) << "\n  CPU " << result.cpu_s_per_ps
       << " s per simulated ps\n";
  return {dipole_field_json(e.header(), result, std::stod(e.dipole), std::stod(e.field)), text.str(), verdict_of(result).warnings};
}

void read_dipole_run(const scene_request& r, dipole_run& e) {
  read_ensemble_run(r, models::water::body_text(), e);
  e.dipole = shortest(positive_number(option(r, "--dipole"), "--dipole"));
  e.field = shortest(positive_number(option(r, "--field"), "--field"));
}

scene_result dipole_field_scene_run(const scene_request& r) {
  dipole_run e;
  read_dipole_run(r, e);
  return in_scalar(e, [&e](auto zero) { return run_in<decltype(zero)>(e); });
}

// The ensemble held (md_simulation), each start's V evaluated first as run_dipole_field does.
std::unique_ptr<held_md_run> dipole_field_scene_hold(const scene_request& r) {
  dipole_run e;
  read_dipole_run(r, e);
  return as_bad_input([&] {
    auto held = in_held_scalar(e, [&e](auto zero) {
      return held_ensemble(models::dipole_field<decltype(zero)>(e.dipole, e.field), e.run, true);
    });
    held->setup = held_setup_of(e);
    return held;
  });
}

}  // namespace

scene dipole_field_scene() {
  auto options = ensemble_options(models::dipole_field_default_T_ps, models::dipole_field_default_runs);
  options.push_back({"--dipole", "1.84", "The dipole in debye"});
  options.push_back({"--field", "2.7", "The field along z in MV/m"});
  return {"dipole-field", "a water molecule's dipole in a constant field: Table I's dH/dV and dLz/<Lz> (vZS section V.B)",
          std::move(options), dipole_field_scene_run, dipole_field_scene_hold};
}

}  // namespace rotlie::runs
