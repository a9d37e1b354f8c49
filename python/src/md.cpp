// md: any scene of the floor's registry (runs/scenes.hpp: free water, a dipole in a field, liquid
// water) as the JSON of `rotlie md --json`, its warnings as Python UserWarnings.
#include <map>
#include <memory>
#include <optional>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/scenes.hpp"

namespace rotlie::python {
namespace {

// options: the scene's options as the command line names them ("--T" → "5"), only those given.
std::string md(const std::string& scene, const std::string& integrator, const std::string& h,
               const std::map<std::string, std::string>& options) {
  auto out = std::make_shared<runs::scene_result>();
  // a scene's progress lines (a run of an ensemble ended, an equilibration stage) are its stop points
  const runs::scene_request request{scene, integrator, h, options, [](const std::string&) { lie::stop_point(); }};
  run_symbolic([request, out] { *out = runs::run_scene(request); });  // a rotor SCHEME:PERM:LABEL is solved symbolically
  for (const auto& w : out->warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) != 0) throw pybind11::error_already_set();
  return out->json.dump();
}

// Every scene's name and options with their defaults, for the Python layer's checks and help.
std::map<std::string, std::map<std::string, std::string>> md_scenes() {
  std::map<std::string, std::map<std::string, std::string>> all;
  for (const auto& s : runs::scenes()) {
    auto& options = all[s.name];
    for (const auto& o : s.options) options[o.name] = o.default_text;
  }
  return all;
}

const char* kind_name(runs::method_kind k) {
  switch (k) {
    case runs::method_kind::tv_splitting: return "tv-splitting";
    case runs::method_kind::kepler_splitting: return "kepler-splitting";
    case runs::method_kind::rk4: return "rk4";
    case runs::method_kind::lgvi: return "lgvi";
    case runs::method_kind::adaptive: return "adaptive";
  }
  return "";
}

// The registry's families (runs/methods.hpp) as dicts, those that step `system` (None: all).
pybind11::list integrators(const std::optional<std::string>& system) {
  namespace py = pybind11;
  std::optional<runs::method_system> only;
  if (system) {
    only = runs::system_named(*system);
    if (!only) throw runs::bad_input("system must be md, spin or binary, got '" + runs::one_line(*system) + "'");
  }
  py::list out;
  for (const auto& f : runs::method_families()) {
    if (only && !f.steps(*only)) continue;
    py::dict d;
    d["name"] = f.name;
    d["kind"] = kind_name(f.kind);
    d["order"] = f.order;
    d["force_evaluations"] = f.kind == runs::method_kind::adaptive ? py::object(py::none()) : py::int_(f.force_evaluations());
    py::list systems;
    for (auto s : f.systems) systems.append(runs::system_name(s));
    d["systems"] = systems;
    d["forms"] = f.forms();
    d["tv_table"] = f.tv_table.empty() ? py::object(py::none()) : py::str(f.tv_table);
    d["rotor"] = f.rotor.empty() ? py::object(py::none()) : py::str(f.rotor);
    d["takes_rotor"] = f.takes_rotor;
    d["lammps_style"] = f.lammps_style ? py::object(py::str(runs::lammps_style_of(f))) : py::object(py::none());
    d["description"] = f.description;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_md(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("md", &md, py::arg("scene"), py::arg("integrator"), py::arg("h"), py::arg("options"));
  m.def("md_scenes", &md_scenes);
  m.def("integrators", &integrators, py::arg("system") = py::none(),
        R"(integrators(system=None) -> list[dict]

The integrator families rotlie knows (the method registry, runs/methods.hpp), those of one system ("md",
"spin" or "binary") or all: name, kind, order, force_evaluations (None: adaptive), systems, forms (as typed:
"SIER2/X", "odeint-rkf78[:TOL]"), tv_table, rotor (the default), takes_rotor, lammps_style, description.)");
}

}  // namespace rotlie::python
