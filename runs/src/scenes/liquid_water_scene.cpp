// liquid-water: rigid TIP3P in a periodic box, vZS section V.C (Fig. 1): the energy fluctuation
// ΔE/ΔV of one integrator and step, with its cost; the equilibrated start is kept in --state.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "rotlie/lie/stop_request.hpp"
#include "rotlie/models/scenes/liquid_water_experiment.hpp"
#include "rotlie/models/scenes/water_model.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/md_json.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/output_file.hpp"
#include "../liquid_water_run.hpp"
#include "scene_support.hpp"

namespace rotlie::runs {
namespace {

using namespace scene_support;

// printf into a string (the summary's column layout).
template <class... A>
std::string line(const char* format, A... a) {
  char buf[512];
  std::snprintf(buf, sizeof buf, format, a...);
  return buf;
}

std::optional<models::liquid_water_nvt_options> thermostat_options(const scene_request& r, const models::md_integrator& integrator) {
  const auto t = read_thermostat(r, integrator);
  if (!t) return std::nullopt;
  models::liquid_water_nvt_options nvt;
  nvt.kelvin = t->kelvin, nvt.friction_per_ps = t->friction_per_ps, nvt.tau_ps = t->tau_ps, nvt.seed = t->seed;
  return nvt;
}

scene_result nvt_result(const models::liquid_water_nvt_result& r) {
  scene_result out;
  out.json = liquid_water_nvt_json(r);
  auto pm = [](const models::mean_error& m, const char* unit) { return line("%.4g ± %.2g %s", m.mean, m.error, unit); };
  out.text = line("liquid water at %g K: %ld TIP3P molecules, %s (%s), h = %g fs, %ld steps (the first fifth settling)\n", r.kelvin, r.molecules,
                  r.integrator.c_str(), r.table.c_str(), r.h_fs, r.steps) +
             "  T translational       " + pm(r.translational_K, "K") + "\n" +
             "  T rotational          " + pm(r.rotational_K, "K") + "\n" +
             (std::isnan(r.rotational_after_o_K.mean) ? std::string()
                                                      : "  T after the O-step   " + pm(r.translational_after_o_K, "K") + " (centres), " +
                                                            pm(r.rotational_after_o_K, "K") + " (rotations)\n") +
             "  T configurational     " + pm(r.configurational_translational_K, "K") + " (centres), " + pm(r.configurational_rotational_K, "K") +
             " (rotations)\n" +
             "  V per molecule        " + pm(r.potential_per_molecule, "kcal/mol") + "\n" +
             line("  g_OO first peak       %.2f at %.3f Å\n", r.rdf_peak_g, r.rdf_peak_r) +
             line("  D                     %.3g × 10⁻⁵ cm²/s\n", r.diffusion) +
             line("  cost                  %.3f ms per step wall, %.3f ms CPU\n", r.ms_per_step, r.cpu_ms_per_step);
  const double tol = 0.05;
  for (const auto& [name, m] : {std::pair{"translational", r.translational_K}, std::pair{"rotational", r.rotational_K}})
    if (std::abs(m.mean / r.kelvin - 1) > tol && std::abs(m.mean - r.kelvin) > 4 * m.error)
      out.warnings.push_back(std::string("the ") + name + " temperature is " + line("%.1f", m.mean) + " K, " + line("%.0f", 100 * tol) +
                             " % or more from the target: the run is too short to settle, or the step too large");
  // the flags every md result carries (md_json.hpp): a run whose temperatures miss the target is flagged unstable
  out.json["unstable"] = !out.warnings.empty();
  out.json["round_off_floor"] = false;
  return out;
}

scene_result liquid_water_scene_run(const scene_request& request) {
  models::liquid_water_run_options o;
  const auto method = method_named(request.integrator, method_system::md, {numeric_body(models::tip3p_body_text())});  // a bad name costs nothing
  o.integrator = method.splitting;
  o.h_fs = positive_number(request.h, "--h");
  o.T_ps = positive_number(option(request, "--T"), "--T");
  o.runs = static_cast<int>(integer_in_range(option(request, "--runs"), "--runs", 1, 1000));
  o.molecules = integer_in_range(option(request, "--molecules"), "--molecules", 2, 10000000);
  o.threads = static_cast<int>(integer_in_range(option(request, "--threads"), "--threads", 1, 64));
  o.state_file = option(request, "--state");
  o.seed = static_cast<std::uint64_t>(integer_in_range(option(request, "--seed"), "--seed", 0, std::numeric_limits<long>::max()));
  o.equilibration_ps = positive_number(option(request, "--equilibrate"), "--equilibrate");
  // whole steps of the equilibration's own step, as --T is bounded: never none, never a run without end
  if (const double steps = o.equilibration_ps * 1000 / o.equilibration_h_fs; !(steps >= 1 && steps <= 1e9))
    throw bad_input("--equilibrate must span 1 to 10⁹ steps of " + significant_text(o.equilibration_h_fs) + " fs, from " +
                    significant_text(o.equilibration_h_fs / 1000) + " to " + significant_text(o.equilibration_h_fs * 1e6) + " ps");
  if (o.T_ps * 1000 / o.h_fs < 10) throw bad_input("--T must span at least 10 steps of --h (the fluctuations are rms over a run)");
  if (o.T_ps * 1000 / o.h_fs * o.runs > 1e9) throw bad_input("--T / --h × --runs exceeds 10⁹ steps");
  o.every = trajectory_every(request, std::round(o.T_ps * 1000 / o.h_fs) * o.runs);
  as_bad_input([&] { models::check_liquid_water_options(o); });  // a box below twice the cutoff
  // --state: checked and its folder locked before the equilibration, so that a state that cannot be
  // written, or a second run on the same folder, costs nothing
  std::optional<exclusive_use> lock;
  if (!o.state_file.empty()) {
    namespace fs = std::filesystem;
    const fs::path state = o.state_file;
    const fs::path folder = state.has_parent_path() ? state.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
      throw bad_input("--state: the folder '" + one_line(folder.string()) + "' does not exist");
    lock.emplace(folder, "--state");
    if (fs::exists(state, ec)) {
      if (!fs::is_regular_file(state, ec)) throw bad_input("--state: '" + one_line(o.state_file) + "' is not a regular file");
    } else if (::access(folder.c_str(), W_OK) != 0) {
      throw bad_input("--state: cannot write into the folder '" + one_line(folder.string()) + "'");
    }
    try {
      writable_target(state);  // a link to nothing is refused now, not after the equilibration
    } catch (const std::runtime_error& e) {
      throw bad_input(std::string("--state: ") + e.what());
    }
    o.write_file = [](const std::string& path, const std::string& text) { write_file_atomically(path, text); };
  }
  o.rotor_table = method.rotor_table();
  const auto nvt = thermostat_options(request, o.integrator);
  o.poll = [] { lie::stop_point(); };  // a caller's stop request (Python's Ctrl-C) ends the run within a step
  auto show = [&request](const std::string& text) {
    if (request.progress) request.progress(text);
  };
  models::rigid_bodies_state<double> start;
  as_bad_input([&] { start = models::liquid_water_start(o, show); });  // a state file of another system, overlaps
  if (nvt) return nvt_result(liquid_water_nvt_run(o, *nvt, start, show));
  const auto r = liquid_water_runs(o, start, show);
  scene_result out;
  out.json = liquid_water_json(r);
  out.text = line("liquid water: %ld TIP3P molecules, box %.4f Å, %s, h = %g fs (h/f = %g fs), %d run(s) of %g ps\n", r.molecules, r.box,
                  r.integrator.c_str(), r.h_fs, r.h_fs / r.f, r.runs, o.T_ps) +
             (std::isnan(r.ratio_error) ? line("  ΔE/ΔV            %.4g ± unknown (one run) %%\n", r.ratio_mean)
                                         : line("  ΔE/ΔV            %.4g ± %.2g %%\n", r.ratio_mean, r.ratio_error)) +
             line("  V per molecule   %.4f kcal/mol\n", r.potential_per_molecule) +
             line("  temperature      %.1f K\n", r.temperature) +
             line("  cost             %.3f ms per step wall, %.3f ms CPU (%ld steps)\n", r.ms_per_step, r.cpu_ms_per_step, r.steps) +
             line("  |ΔP| (momentum)  %.2e g/mol·Å/fs\n", r.momentum_drift);
  out.warnings = verdict_of(r).warnings;
  return out;
}

}  // namespace

scene liquid_water_scene() {
  return {"liquid-water",
          "rigid TIP3P water in a periodic box: Fig. 1's energy fluctuation dE/dV and the cost per step (vZS section V.C)",
          {{"--T", "1", "Simulated time per run in ps, rounded to whole steps"},
           {"--runs", "9", "Ensemble size"},
           {"--molecules", "512", "Molecules in the box (at least 365)"},
           {"--threads", "2", "Threads of the force loop (results do not depend on it)"},
           {"--state", "", "A state file, read if it exists, else the equilibrated start is written there"},
           {"--equilibrate", "10", "Equilibration of a new start in ps (Berendsen at 297 K; not run when --state is read)"},
           thermostat_option_temperature(), thermostat_option_friction(), thermostat_option_tau(),
           {"--seed", "1", "Seed of the lattice start and of the Langevin noise"},
           every_option()},
          liquid_water_scene_run};
}

}  // namespace rotlie::runs
