// `rotlie md --scene liquid-water` (see md_liquid_water.hpp).
#include "md_liquid_water.hpp"

#include <cstdio>
#include <iostream>
#include <optional>

#include "arguments.hpp"
#include "rotlie/reports/md_io.hpp"
#include "progress.hpp"
#include "rotlie/models/scenes/liquid_water_experiment.hpp"
#include "rotlie/models/scenes/water_model.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/scheme_names.hpp"

namespace rotlie::app {

namespace {

// The options checked, and --integrator parsed (once: everything below takes the parsed integrator).
struct checked_options {
  models::liquid_water_run_options run;
  models::md_integrator integrator;
};

checked_options checked(const md_liquid_water_options& o) {
  checked_options c;
  auto& r = c.run;
  r.integrator = o.integrator;
  try {
    c.integrator = models::md_integrator_named(o.integrator);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--integrator: ") + e.what());
  }
  if (o.h.empty()) throw usage_error("--h is required (the step in fs)");
  r.h_fs = runs::positive_number(o.h, "--h");
  r.T_ps = runs::positive_number(o.T, "--T");
  r.runs = static_cast<int>(parse_integer_in_range(o.runs, "--runs", 1, 1000));
  r.molecules = parse_integer_in_range(o.molecules, "--molecules", 2, 10000000);
  r.threads = static_cast<int>(parse_integer_in_range(o.threads, "--threads", 1, 64));
  r.state_file = o.state;
  if (r.T_ps * 1000 / r.h_fs < 10) throw usage_error("--T must span at least 10 steps of --h (the fluctuations are rms over a run)");
  if (r.T_ps * 1000 / r.h_fs * r.runs > 1e9) throw usage_error("--T / --h × --runs exceeds 10⁹ steps");
  try {
    models::check_liquid_water_options(r);
  } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());
  }
  return c;
}

// The rotor table of SIER2/X or SIER4/X (a reference name, or SCHEME:PERM:LABEL solved for the
// TIP3P body); empty for the integrators with their own rotor. A table file solved for another
// body is refused by the lookup.
std::optional<schemes::scheme_table> rotor_of(const models::md_integrator& integrator) {
  if (integrator.rotor != models::rotor_kind::table) return std::nullopt;
  try {
    return runs::scheme_named(integrator.rotor_table, runs::numeric_body(models::tip3p_body_text()), runs::foreign_table::refuse);
  } catch (const runs::bad_input& e) {
    std::string why = e.what();
    if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
    throw usage_error("--integrator " + integrator.name + ": " + why);
  }
}

}  // namespace

int run_md_liquid_water(const md_liquid_water_options& options) {
  auto [o, integrator] = checked(options);
  const auto rotor = rotor_of(integrator);  // before the equilibration: a bad name costs nothing
  o.rotor_table = rotor ? &*rotor : nullptr;
  progress_line progress;
  auto show = [&](const std::string& line) { progress.show(line); };
  models::rigid_bodies_state<double> start;
  try {
    start = models::liquid_water_start(o, show);
  } catch (const std::invalid_argument& e) {  // a state file of another system, overlapping molecules
    throw usage_error(e.what());
  }
  const auto r = models::run_liquid_water(o, integrator, start, show);
  if (options.json) {
    std::cout << reports::liquid_water_json(r).dump(2) << "\n";
  } else {
    std::printf("liquid water: %ld TIP3P molecules, box %.4f Å, %s, h = %g fs (h/f = %g fs), %d run(s) of %g ps\n", r.molecules, r.box,
                r.integrator.c_str(), r.h_fs, r.h_fs / r.f, r.runs, o.T_ps);
    std::printf("  ΔE/ΔV            %.4g ± %.2g %%\n", r.ratio_mean, r.ratio_error);
    std::printf("  V per molecule   %.4f kcal/mol\n", r.potential_per_molecule);
    std::printf("  temperature      %.1f K\n", r.temperature);
    std::printf("  cost             %.3f ms per step wall, %.3f ms CPU (%ld steps)\n", r.ms_per_step, r.cpu_ms_per_step, r.steps);
    std::printf("  |ΔP| (momentum)  %.2e g/mol·Å/fs\n", r.momentum_drift);
  }
  return 0;
}

}  // namespace rotlie::app
