#pragma once
// The ensemble scenes of van Zon & Schofield (free water, a dipole in a field): how their common
// options become one run (integrator, rotor, step, length, ensemble, seed, scalar), checked in the
// order the command line has always reported them.
#include <boost/multiprecision/float128.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "rotlie/lie/stop_request.hpp"
#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/runs/md_json.hpp"
#include "rotlie/runs/md_simulation.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "scene_support.hpp"

namespace rotlie::runs::scene_support {

inline constexpr double max_total_steps = 2e9;  // runs × T/h: about an hour of SIER2 in double

struct ensemble_run {
  std::string scene, scalar;
  std::optional<schemes::scheme_table> rotor;  ///< X of SIER2/X, SIER4/X, solved for the scene's body
  models::md_run_options run;                  ///< run.rotor_table points into `rotor`

  ensemble_run() = default;
  ensemble_run(const ensemble_run&) = delete;  // run.rotor_table points into this object
  ensemble_run& operator=(const ensemble_run&) = delete;

  md_run_header header() const { return {scene, run.integrator.name, scalar, run.h_fs, run.T_ps, run.runs, run.seed}; }
};

/// Fills `e` from the request (every option present); throws bad_input naming the option. An integrator
/// with a thermostat is refused unless the scene runs one (thermostat_allowed).
inline void read_ensemble_run(const scene_request& r, const std::string& body_text, ensemble_run& e, bool thermostat_allowed = false) {
  e.scene = r.scene;
  e.scalar = option(r, "--scalar");
  if (e.scalar != "double" && e.scalar != "long-double" && e.scalar != "float128")
    throw bad_input("--scalar must be double, long-double or float128, got '" + e.scalar + "'");
  auto method = method_named(r.integrator, method_system::md, {numeric_body(body_text)});
  if (method.splitting.thermostat && !thermostat_allowed)
    throw bad_input("--integrator " + one_line(r.integrator) + ": a thermostat runs in the free-water and liquid-water scenes' runs, not in " +
                    r.scene + "'s or in a held simulation (md_simulation)");
  e.run.integrator = std::move(method.splitting);
  if (!method.rotors.empty()) e.rotor = std::move(method.rotors.front());
  e.run.rotor_table = e.rotor ? &*e.rotor : nullptr;
  e.run.h_fs = positive_number(r.h, "--h");
  e.run.T_ps = positive_number(option(r, "--T"), "--T");
  e.run.runs = integer_in_range(option(r, "--runs"), "--runs", 1, 1'000'000);
  e.run.seed = static_cast<std::uint64_t>(integer_in_range(option(r, "--seed"), "--seed", 0, std::numeric_limits<long>::max()));
  const double steps = std::round(e.run.T_ps * 1000 / e.run.h_fs);
  if (steps < 1)
    throw bad_input("--T must be at least one step --h (T = " + option(r, "--T") + " ps, h = " + r.h + " fs)");
  if (steps * static_cast<double>(e.run.runs) > max_total_steps)
    throw bad_input("--runs × --T/--h = " + shortest(steps * static_cast<double>(e.run.runs)) + " steps is over the limit of " +
                    shortest(max_total_steps));
  e.run.every = trajectory_every(r, steps);
  e.run.poll = [] { lie::stop_point(); };  // a caller's stop request (Python's Ctrl-C) ends the ensemble within 64 steps
  if (r.progress)
    e.run.progress = [&p = r.progress](long done, long runs) { p("run " + std::to_string(done) + " of " + std::to_string(runs)); };
}

/// The summary's first line: "WHAT, INTEGRATOR (f = F), h = H fs (h/f = H/F fs), R runs of S steps (T ps), seed N, SCALAR".
inline std::string run_summary(const ensemble_run& e, const std::string& what, int f, long steps) {
  std::ostringstream text;
  text << what << ", " << e.run.integrator.name << " (f = " << f << "), h = " << e.run.h_fs << " fs (h/f = " << e.run.h_fs / f << " fs), "
       << e.run.runs << " runs of " << steps << " steps (" << e.run.T_ps << " ps), seed " << e.run.seed << ", " << e.scalar << "\n";
  return text.str();
}

/// f(T{}) in the scalar T that e.scalar names; a value the models refuse (a table that does not fit the
/// body or the split) becomes bad_input.
template <class F>
scene_result in_scalar(const ensemble_run& e, F&& f) {
  return as_bad_input([&] {
    if (e.scalar == "double") return f(double{});
    if (e.scalar == "long-double") return f(static_cast<long double>(0));
    return f(boost::multiprecision::float128{});
  });
}

/// f(T{}) as in_scalar, for what returns a held run.
template <class F>
std::unique_ptr<held_md_run> in_held_scalar(const ensemble_run& e, F&& f) {
  if (e.scalar == "double") return f(double{});
  if (e.scalar == "long-double") return f(static_cast<long double>(0));
  return f(boost::multiprecision::float128{});
}

/// What a held ensemble is of.
inline md_held_setup held_setup_of(const ensemble_run& e) {
  return {e.scene, e.run.integrator.name, e.scalar, e.run.h_fs, e.run.runs, static_cast<unsigned long>(e.run.seed)};
}

/// The options of an ensemble scene, with its defaults.
inline std::vector<scene_option> ensemble_options(double default_T_ps, long default_runs) {
  return {{"--T", shortest(default_T_ps), "Simulated time per run in ps, rounded to whole steps"},
          {"--runs", std::to_string(default_runs), "Ensemble size"},
          {"--seed", "1", "Seed of the canonical initial conditions (the same seed, the same numbers)"},
          {"--scalar", "double", "double, long-double or float128"},
          every_option()};
}

}  // namespace rotlie::runs::scene_support
