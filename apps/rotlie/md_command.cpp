// md: the van Zon & Schofield scenes on the command line (free water: the orientation error time τ;
// dipole in a field: Table I's ΔH/ΔV and ΔL_z/⟨L_z⟩), any integrator, in double, long double or float128.
#include <boost/multiprecision/float128.hpp>

#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/reports/md_io.hpp"
#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/scheme_names.hpp"

namespace rotlie::app {
namespace {

using quad = boost::multiprecision::float128;

constexpr double max_total_steps = 2e9;  // runs × T/h: about an hour of SIER2 in double

// The shortest decimal that reads back as x (so that long double and float128 read the same number).
std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, ec == std::errc() ? end : buf);
}

std::string water_body_text() {
  return std::string(models::water::moments_text[0]) + "," + models::water::moments_text[1] + "," + models::water::moments_text[2];
}

struct resolved_run {
  models::md_integrator integrator;  ///< --integrator, parsed once here
  models::md_run_options run;
  std::optional<schemes::scheme_table> rotor;  ///< the free-rotation table, resolved for the water body
  std::string dipole, field;
};

reports::md_run_header header_of(const md_options& o, const resolved_run& r) {
  return {o.scene, o.integrator, o.scalar, r.run.h_fs, r.run.T_ps, r.run.runs, r.run.seed};
}

template <class T>
int report_free_water(const md_options& o, const resolved_run& r) {
  const auto result = models::run_free_water(models::free_water<T>{}, r.integrator, r.run);
  if (!result.finite) throw std::runtime_error("the integration diverged (non-finite attitude): the step is beyond the integrator's stability limit");
  if (o.json) {
    std::cout << reports::free_water_json(header_of(o, r), result).dump(2) << "\n";
  } else {
    std::cout << "free water, " << o.integrator << " (f = " << result.f << "), h = " << r.run.h_fs << " fs, " << r.run.runs
              << " runs of " << result.steps << " steps (" << r.run.T_ps << " ps), seed " << r.run.seed << ", " << o.scalar
              << "\n  tau = " << result.tau_ps << " ± " << result.tau_error_ps << " ps (delta = t/(10 tau) fitted over " << result.fitted_samples << " of "
              << result.t_ps.size() << " samples)\n  delta(T) = " << result.delta.back() << " (exact reference: "
              << result.reference_delta.back() << ")\n  CPU " << result.cpu_s_per_ps << " s per simulated ps\n";
  }
  if (result.fitted_samples < 2)
    std::cerr << "rotlie: warning: fewer than two samples have 10 × reference error < delta <= 0.1: tau is not defined "
                 "(run longer if delta is at round-off, shorter if it has saturated)\n";
  return 0;
}

template <class T>
int report_dipole_field(const md_options& o, const resolved_run& r) {
  const auto result = models::run_dipole_field(models::dipole_field<T>(r.dipole, r.field), r.integrator, r.run);
  if (result.failed_runs == r.run.runs)
    throw std::runtime_error("every run diverged (non-finite energy): the step is beyond the integrator's stability limit");
  if (o.json) {
    std::cout << reports::dipole_field_json(header_of(o, r), result, std::stod(r.dipole), std::stod(r.field)).dump(2) << "\n";
  } else {
    std::cout << "dipole in a field, " << o.integrator << " (f = " << result.f << "), h = " << r.run.h_fs << " fs (h/f = "
              << r.run.h_fs / result.f << " fs), " << r.run.runs << " runs of " << result.steps << " steps (" << r.run.T_ps
              << " ps), seed " << r.run.seed << ", " << o.scalar << "\n  dH/dV = " << result.dH.mean << " ± " << result.dH.error
              << " %\n  dLz/<Lz> = " << result.dLz.mean << " ± " << result.dLz.error << "\n  CPU " << result.cpu_s_per_ps
              << " s per simulated ps\n";
  }
  if (result.failed_runs > 0)
    std::cerr << "rotlie: warning: " << result.failed_runs << " of " << r.run.runs
              << " runs diverged (non-finite energy) and are left out of the means\n";
  return 0;
}

template <class T>
int run_md_in(const md_options& o, const resolved_run& r) {
  return o.scene == "free-water" ? report_free_water<T>(o, r) : report_dipole_field<T>(o, r);
}

}  // namespace

int run_md(const md_options& o) {
  if (o.scene != "free-water" && o.scene != "dipole-field")
    throw usage_error("--scene must be free-water, dipole-field or liquid-water, got '" + o.scene + "'");
  if (o.scalar != "double" && o.scalar != "long-double" && o.scalar != "float128")
    throw usage_error("--scalar must be double, long-double or float128, got '" + o.scalar + "'");
  resolved_run r;
  try {
    r.integrator = models::md_integrator_named(o.integrator);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--integrator: ") + e.what());
  }
  if (r.integrator.rotor == models::rotor_kind::table) {
    // a reference name or a dedicated SCHEME:PERM:LABEL, solved for the scene's water molecule
    try {
      r.rotor = runs::scheme_named(r.integrator.rotor_table, runs::numeric_body(water_body_text()), runs::foreign_table::refuse);
    } catch (const runs::bad_input& e) {
      std::string why = e.what();
      if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
      throw usage_error("--integrator " + o.integrator + ": " + why);
    }
    r.run.rotor_table = &*r.rotor;
  }
  const bool free = o.scene == "free-water";
  r.run.integrator = o.integrator;
  r.run.h_fs = runs::positive_number(o.h, "--h");
  r.run.T_ps = runs::positive_number(o.T.empty() ? shortest(free ? models::free_water_default_T_ps : models::dipole_field_default_T_ps) : o.T, "--T");
  r.run.runs = o.runs.empty() ? (free ? models::free_water_default_runs : models::dipole_field_default_runs)
                              : parse_integer_in_range(o.runs, "--runs", 1, 1'000'000);
  r.run.seed = static_cast<std::uint64_t>(parse_integer_in_range(o.seed, "--seed", 0, std::numeric_limits<long>::max()));
  const double steps = std::round(r.run.T_ps * 1000 / r.run.h_fs);
  if (steps < 1) throw usage_error("--T must be at least one step --h (T = " + o.T + " ps, h = " + o.h + " fs)");
  if (steps * static_cast<double>(r.run.runs) > max_total_steps)
    throw usage_error("--runs × --T/--h = " + shortest(steps * static_cast<double>(r.run.runs)) + " steps is over the limit of " +
                      shortest(max_total_steps));
  if (!free || o.dipole != "1.84" || o.field != "2.7") {
    if (free) throw usage_error("--dipole and --field apply to the dipole-field scene only");
    r.dipole = shortest(runs::positive_number(o.dipole, "--dipole"));
    r.field = shortest(runs::positive_number(o.field, "--field"));
  }
  progress_line progress;
  r.run.progress = [&progress](long done, long runs) {
    progress.show("run " + std::to_string(done) + " of " + std::to_string(runs));
  };
  try {
    if (o.scalar == "double") return run_md_in<double>(o, r);
    if (o.scalar == "long-double") return run_md_in<long double>(o, r);
    return run_md_in<quad>(o, r);
  } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());  // a table that does not fit the body or the split
  }
}

}  // namespace rotlie::app
