// md: any scene of the floor's registry (runs/scenes.hpp: free water, a dipole in a field, liquid
// water) as the JSON of `rotlie md --json`, its warnings as Python UserWarnings.
#include <map>
#include <memory>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/lie/stop_request.hpp"
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

}  // namespace

void bind_md(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("md", &md, py::arg("scene"), py::arg("integrator"), py::arg("h"), py::arg("options"));
  m.def("md_scenes", &md_scenes);
}

}  // namespace rotlie::python
