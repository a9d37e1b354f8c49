// spin_simulation: the spin–orbit run held (runs::spin_simulation) as rotlie.spin_simulation(...),
// rotlie.spin's keywords but T and every; integrate(t) to an absolute time in orbits.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "arguments.hpp"
#include "bindings.hpp"
#include "held_simulation.hpp"
#include "interruption.hpp"
#include "rotlie/runs/spin_simulation.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;
using held_spin = held<runs::spin_simulation>;

std::unique_ptr<held_spin> spin_simulation(const py::object& body, const py::object& e, const std::string& integrator, const py::object& h,
                                           const py::object& theta0, const py::object& omega0, const py::object& obliquity,
                                           const std::string& scalar) {
  const std::string step = number_argument(h, "h");
  // T = h: the setup's checks for one step, whose h is then the step as given
  runs::spin_request q{spin_body_argument(body), number_argument(e, "e"), integrator, step, step,
                       number_argument(theta0, "theta0"), number_argument(omega0, "omega0"), number_argument(obliquity, "obliquity"),
                       scalar, "0"};
  auto out = std::make_shared<std::unique_ptr<held_spin>>();
  run_symbolic([q, out] {  // a rotor SCHEME:PERM:LABEL is solved symbolically
    *out = std::make_unique<held_spin>(held_spin{runs::spin_simulation(runs::spin_setup_of(q))});
  });
  return std::move(*out);
}

py::array_t<double> vector3(const models::vec3<double>& v) { return py::array_t<double>(3, v.data()); }

}  // namespace

void bind_spin_simulation(py::module_& m) {
  py::class_<held_spin>(m, "SpinSimulation", "A spin–orbit run held between calls (rotlie.spin_simulation)")
      .def("integrate", &integrate_held<runs::spin_simulation>, py::arg("t"),
           "To the absolute time t (orbits) in whole steps h (the last step's end at most t, round-off aside); "
           "a t before the current step raises ValueError")
      .def("step", [](held_spin& s) { s.sim.step(); }, "one step h")
      .def_property_readonly("t", [](const held_spin& s) { return s.sim.t(); }, "steps × h, orbits")
      .def_property_readonly("steps", [](const held_spin& s) { return s.sim.steps(); })
      .def_property_readonly("h", [](const held_spin& s) { return s.sim.setup().h; }, "the step, in orbits")
      .def_property_readonly("body", [](const held_spin& s) { return s.sim.setup().body.name; })
      .def_property_readonly("integrator", [](const held_spin& s) { return s.sim.setup().method.name; })
      .def_property_readonly("scalar", [](const held_spin& s) { return s.sim.setup().scalar; })
      .def_property_readonly("e", [](const held_spin& s) { return s.sim.setup().e; })
      .def_property_readonly("Q", [](const held_spin& s) { return matrix(s.sim.Q().a); }, "attitude, columns the body axes")
      .def_property_readonly("G", [](const held_spin& s) { return vector3(s.sim.G()); }, "angular momentum in the body frame")
      .def_property_readonly("omega_body", [](const held_spin& s) { return vector3(s.sim.omega_body()); },
                             "angular velocity in the body frame (units of n)")
      .def_property_readonly("theta", [](const held_spin& s) { return s.sim.theta(); })
      .def_property_readonly("energy", [](const held_spin& s) { return s.sim.energy(); }, "T + V(t)")
      .def_property_readonly("evaluations", [](const held_spin& s) { return s.sim.evaluations(); })
      .def("__repr__", [](const held_spin& s) {
        return "<SpinSimulation " + s.sim.setup().body.name + " " + s.sim.setup().method.name + ", step " + std::to_string(s.sim.steps()) + ">";
      });
  m.def("spin_simulation", &spin_simulation, py::arg("body"), py::arg("e"), py::arg("integrator"), py::arg("h"), py::arg("theta0") = 0,
        py::arg("omega0") = 1, py::arg("obliquity") = 0, py::arg("scalar") = "double",
        R"(spin_simulation(body, e, integrator, h, theta0=0, omega0=1, obliquity=0, scalar="double") -> SpinSimulation

The run of rotlie.spin held at t = 0 (its keywords but T and every): integrate(t) advances it to the absolute
time t (orbits) in whole steps h and continues from there, so integrate(T/2) then integrate(T) gives the bits
of integrate(T). Attributes: t, steps, Q, G, omega_body, theta, energy, evaluations.)");
}

}  // namespace rotlie::python
