// Bodies: exact moments checked by the floor (runs::required_body: positive, eq. 77), returned as
// exact text so that Python never holds a CLN number.
#include <pybind11/stl.h>

#include <array>
#include <memory>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/map_file.hpp"

namespace rotlie::python {
namespace {

std::array<std::string, 3> exact_moments(const std::string& text) {
  auto out = std::make_shared<std::array<std::string, 3>>();
  run_symbolic([text, out] {
    const auto body = runs::required_body(text);
    for (std::size_t i = 0; i < 3; ++i) (*out)[i] = runs::fraction_text(body.I[i]);
  });
  return *out;
}

}  // namespace

void bind_bodies(pybind11::module_& m) {
  m.def("exact_moments", &exact_moments, pybind11::arg("text"),
        "The exact moments (p/q text) of a body named as the command line's --inertia; ValueError when "
        "they are not a rigid body's (eq. 77).");
}

}  // namespace rotlie::python
