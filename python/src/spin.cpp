// spin: the spin–orbit scene (runs::spin_run, `rotlie spin`) as rotlie.spin(...) with typed keywords,
// its result a SpinResult whose attributes are the JSON's fields (Q a 3×3 array, the trajectory's
// samples as arrays) and whose to_dict() is `rotlie spin --json`'s object.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "arguments.hpp"
#include "binary_keywords.hpp"
#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/spin_io.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;

struct spin_object {
  runs::spin_result result;
  std::string json;  ///< `rotlie spin --json`'s text
};

struct trajectory_object {
  runs::spin_trajectory samples;
  long every = 0;
};

spin_object spin(const py::object& body, const py::object& e, const std::string& integrator, const py::object& h, const py::object& T,
                 const py::object& theta0, const py::object& omega0, const py::object& obliquity, const std::string& scalar,
                 const py::object& every, const py::object& accuracy, bool no_error_estimate) {
  runs::spin_request q{spin_body_argument(body), number_argument(e, "e"), integrator, number_argument(h, "h"), number_argument(T, "T"),
                       number_argument(theta0, "theta0"), number_argument(omega0, "omega0"), number_argument(obliquity, "obliquity"),
                       scalar, every_argument(every), numbers_argument(accuracy, "accuracy"), no_error_estimate};
  auto out = std::make_shared<spin_object>();
  auto setup = std::make_shared<runs::spin_setup>();
  run_symbolic([q, setup] { *setup = runs::spin_setup_of(q); });  // a rotor SCHEME:PERM:LABEL is solved symbolically
  // the run itself stops on Ctrl-C within 64 steps, and holds no lock meanwhile
  run_cancellable([&](const cancellation& cancel) {
    out->result = runs::spin_run(*setup, [&cancel] { return cancel.requested(); });
    out->json = runs::spin_json(out->result).dump();
  });
  for (const auto& w : out->result.check.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) != 0) throw py::error_already_set();
  return std::move(*out);
}

}  // namespace

void bind_spin(py::module_& m) {
  py::class_<trajectory_object>(m, "SpinTrajectory", "The state every K steps from the start, as arrays")
      .def_readonly("every", &trajectory_object::every)
      .def_property_readonly("t", [](const trajectory_object& s) { return vector_array(s.samples.t); }, "times in orbits, shape (N,)")
      .def_property_readonly("Q", [](const trajectory_object& s) { return rows_array(s.samples.Q, {3, 3}); }, "attitudes, shape (N, 3, 3)")
      .def_property_readonly("omega_body", [](const trajectory_object& s) { return rows_array(s.samples.omega_body, {3}); },
                             "angular velocities in the body frame (units of n), shape (N, 3)")
      .def_property_readonly("energy", [](const trajectory_object& s) { return vector_array(s.samples.energy); }, "T + V(t), shape (N,)");
  py::class_<spin_object> result(m, "SpinResult", "The result of rotlie.spin: the fields of `rotlie spin --json` as attributes");
  def_run_properties<spin_object>(result, "the step taken, in orbits", "spin");
  result.def_property_readonly("body", [](const spin_object& s) { return s.result.setup.body.name; })
      .def_property_readonly("scalar", [](const spin_object& s) { return s.result.setup.scalar; })
      .def_property_readonly("e", [](const spin_object& s) { return s.result.setup.e; })
      .def_property_readonly("Q", [](const spin_object& s) { return matrix(s.result.Q.a); }, "final attitude, columns the body axes")
      .def_property_readonly("omega_body", [](const spin_object& s) {
        return py::array_t<double>(3, s.result.omega_body.data());
      })
      .def_property_readonly("theta", [](const spin_object& s) { return s.result.theta; })
      .def_property_readonly("energy_start", [](const spin_object& s) { return s.result.energy_start; })
      .def_property_readonly("energy_end", [](const spin_object& s) { return s.result.energy_end; })
      .def_property_readonly("conserved", [](const spin_object& s) -> py::object {
        // an owning object: an item accessor would refer to the parsed dictionary after it is freed
        const py::dict all = py::module_::import("json").attr("loads")(s.json);
        return all["conserved"];
      })
      .def_property_readonly("inaccurate", [](const spin_object& s) { return s.result.check.inaccurate; },
                             "the error estimate beyond the accuracy asked for")
      .def_property_readonly("error_estimate", [](const spin_object& s) -> py::object {
        const py::dict all = py::module_::import("json").attr("loads")(s.json);
        return all["error_estimate"];
      }, "{attitude_rad, spin_rate_rel, order, step_ratio, cpu_s}: the same method at twice the step alongside, or None")
      .def_property_readonly("trajectory", [](const spin_object& s) -> py::object {
        if (s.result.setup.every <= 0) return py::none();
        return py::cast(trajectory_object{s.result.trajectory, s.result.setup.every});
      }, "the samples every K steps (every=K), or None")
      .def("__repr__", [](const spin_object& s) {
        return "<SpinResult " + s.result.setup.body.name + " " + s.result.setup.method.name + ", " + std::to_string(s.result.setup.steps) +
               " steps" + (s.result.check.unstable ? ", unstable>" : ">");
      });
  m.def("spin", &spin, py::arg("body"), py::arg("e"), py::arg("integrator"), py::arg("h"), py::arg("T"), py::arg("theta0") = 0,
        py::arg("omega0") = 1, py::arg("obliquity") = 0, py::arg("scalar") = "double", py::arg("every") = py::none(),
        py::arg("accuracy") = "1e-3,1e-2", py::arg("no_error_estimate") = false,
        (R"(spin(body, e, integrator, h, T, theta0=0, omega0=1, obliquity=0, scalar="double", every=None, accuracy="1e-3,1e-2", no_error_estimate=False) -> SpinResult

A triaxial body on a fixed Kepler orbit under the quadrupole torque, as ``rotlie spin`` (docs/spin_orbit.md).
body: "Hyperion", "Moon", "Mercury", "A,B,C", a Body or three moments (A <= B <= C); e: eccentricity in [0, 1);
integrator: )" + runs::method_names_text(runs::method_system::spin) + R"( (rotlie.integrators("spin"));
h: the step as a fraction of the orbit (str, Fraction or float), T: orbits, a whole number of steps;
theta0, obliquity (rad), omega0 (units of n): the start; every: a trajectory sample every K steps
(SpinResult.trajectory: t, Q, omega_body, energy arrays). A fixed-step run is repeated at twice the step alongside
(SpinResult.error_estimate: attitude_rad, spin_rate_rel); beyond accuracy, REL or (REL, RAD) with REL the spin rate's
relative error and RAD the attitude's angle, it is marked inaccurate; no_error_estimate=True skips it. An untrusted
run (SpinResult.unstable) or an inaccurate one also raises a UserWarning.)").c_str());
}

}  // namespace rotlie::python
