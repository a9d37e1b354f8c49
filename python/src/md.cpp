// md: the van Zon & Schofield scenes (free water: the orientation-error time τ; a dipole in a
// field: Table I's ΔH/ΔV and ΔL_z/⟨L_z⟩) with any integrator and scalar, as the JSON of
// `rotlie md --json`, by the same floor and models calls as the command line. The liquid-water
// scene is the command line's only.
#include <charconv>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "rotlie/reports/md_io.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::python {
namespace {

constexpr double max_total_steps = 2e9;  // runs × T/h, as `rotlie md`

struct md_request {
  std::string scene, integrator, h, T, runs, seed, scalar, dipole, field;
};

// The shortest decimal that reads back as x (so that long double and float128 read the same number).
std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, ec == std::errc() ? end : buf);
}

struct resolved_run {
  models::md_integrator integrator;
  models::md_run_options run;
  std::optional<schemes::scheme_table> rotor;
  std::string dipole, field;
};

reports::md_run_header header_of(const md_request& o, const resolved_run& r) {
  return {o.scene, o.integrator, o.scalar, r.run.h_fs, r.run.T_ps, r.run.runs, r.run.seed};
}

template <class T>
std::string run_in(const md_request& o, const resolved_run& r, std::vector<std::string>& warnings) {
  if (o.scene == "free-water") {
    const auto result = models::run_free_water(models::free_water<T>{}, r.integrator, r.run);
    if (!result.finite)
      throw std::runtime_error("the integration diverged (non-finite attitude): the step is beyond the integrator's stability limit");
    if (result.fitted_samples < 2)
      warnings.push_back("fewer than two samples have 10 × reference error < delta <= 0.1: tau is not defined "
                         "(run longer if delta is at round-off, shorter if it has saturated)");
    return reports::free_water_json(header_of(o, r), result).dump();
  }
  const auto result = models::run_dipole_field(models::dipole_field<T>(r.dipole, r.field), r.integrator, r.run);
  if (result.failed_runs == r.run.runs)
    throw std::runtime_error("every run diverged (non-finite energy): the step is beyond the integrator's stability limit");
  if (result.failed_runs > 0)
    warnings.push_back(std::to_string(result.failed_runs) + " of " + std::to_string(r.run.runs) +
                       " runs diverged (non-finite energy) and are left out of the means");
  return reports::dipole_field_json(header_of(o, r), result, std::stod(r.dipole), std::stod(r.field)).dump();
}

std::string md_json(const md_request& o, std::vector<std::string>& warnings) {
  if (o.scene == "liquid-water")
    throw runs::bad_input("--scene liquid-water is run by the command line only (rotlie md --scene liquid-water)");
  if (o.scene != "free-water" && o.scene != "dipole-field")
    throw runs::bad_input("--scene must be free-water, dipole-field or liquid-water, got '" + o.scene + "'");
  if (o.scalar != "double" && o.scalar != "long-double" && o.scalar != "float128")
    throw runs::bad_input("--scalar must be double, long-double or float128, got '" + o.scalar + "'");
  resolved_run r;
  try {
    r.integrator = models::md_integrator_named(o.integrator);
  } catch (const std::invalid_argument& e) {
    throw runs::bad_input(std::string("--integrator: ") + e.what());
  }
  if (r.integrator.rotor == models::rotor_kind::table) {
    const std::string water = std::string(models::water::moments_text[0]) + "," + models::water::moments_text[1] + "," +
                              models::water::moments_text[2];
    try {
      r.rotor = runs::scheme_named(r.integrator.rotor_table, runs::numeric_body(water), runs::foreign_table::refuse);
    } catch (const runs::bad_input& e) {
      std::string why = e.what();
      if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
      throw runs::bad_input("--integrator " + o.integrator + ": " + why);
    }
    r.run.rotor_table = &*r.rotor;
  }
  const bool free = o.scene == "free-water";
  r.run.integrator = o.integrator;
  r.run.h_fs = runs::positive_number(o.h, "--h");
  r.run.T_ps = runs::positive_number(
      o.T.empty() ? shortest(free ? models::free_water_default_T_ps : models::dipole_field_default_T_ps) : o.T, "--T");
  r.run.runs = o.runs.empty() ? (free ? models::free_water_default_runs : models::dipole_field_default_runs)
                              : runs::integer_in_range(o.runs, "--runs", 1, 1'000'000);
  r.run.seed = static_cast<std::uint64_t>(runs::integer_in_range(o.seed, "--seed", 0, std::numeric_limits<long>::max()));
  const double steps = std::round(r.run.T_ps * 1000 / r.run.h_fs);
  if (steps < 1) throw runs::bad_input("--T must be at least one step --h (T = " + o.T + " ps, h = " + o.h + " fs)");
  if (steps * static_cast<double>(r.run.runs) > max_total_steps)
    throw runs::bad_input("--runs × --T/--h = " + shortest(steps * static_cast<double>(r.run.runs)) +
                          " steps is over the limit of " + shortest(max_total_steps));
  if (!free || o.dipole != "1.84" || o.field != "2.7") {
    if (free) throw runs::bad_input("--dipole and --field apply to the dipole-field scene only");
    r.dipole = shortest(runs::positive_number(o.dipole, "--dipole"));
    r.field = shortest(runs::positive_number(o.field, "--field"));
  }
  if (o.scalar == "double") return run_in<double>(o, r, warnings);
  if (o.scalar == "long-double") return run_in<long double>(o, r, warnings);
  return run_in<quad>(o, r, warnings);
}

std::string md(const std::string& scene, const std::string& integrator, const std::string& h, const std::string& T,
               const std::string& runs_, const std::string& seed, const std::string& scalar, const std::string& dipole,
               const std::string& field) {
  auto out = std::make_shared<std::string>();
  auto warnings = std::make_shared<std::vector<std::string>>();
  const md_request o{scene, integrator, h, T, runs_, seed, scalar, dipole, field};
  run_symbolic([o, out, warnings] { *out = md_json(o, *warnings); });
  for (const auto& w : *warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) != 0) throw pybind11::error_already_set();
  return *out;
}

}  // namespace

void bind_md(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("md", &md, py::arg("scene"), py::arg("integrator"), py::arg("h"), py::arg("T"), py::arg("runs"), py::arg("seed"),
        py::arg("scalar"), py::arg("dipole"), py::arg("field"));
}

}  // namespace rotlie::python
