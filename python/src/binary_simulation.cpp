// binary_simulation: the full two-body problem as a simulation the user holds (runs::binary_simulation),
// REBOUND's shape: rotlie.binary_simulation(...) takes rotlie.binary's keywords but T and every, and
// sim.integrate(t) continues to the absolute time t in whole steps. A Ctrl-C stops it at a step's end
// (KeyboardInterrupt; the simulation keeps the state reached). copy.copy(sim) saves it whole.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "arguments.hpp"
#include "binary_keywords.hpp"
#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_simulation.hpp"

namespace rotlie::python {
namespace {

py::array_t<double> state_array(const models::vec3<double>& x) { return py::array_t<double>(3, x.data()); }

std::shared_ptr<runs::binary_simulation> binary_simulation(const py::kwargs& keywords) {
  auto q = binary_keywords(keywords, "binary_simulation", true);
  if (q.h.empty()) throw std::invalid_argument("binary_simulation: h (the step in seconds) is required");
  q.T = "0";
  std::shared_ptr<runs::binary_simulation> out;
  run_symbolic([q, &out] { out = std::make_shared<runs::binary_simulation>(runs::binary_setup_of(q)); });  // a rotor may be solved symbolically
  return out;
}

void integrate_to(runs::binary_simulation& sim, double t) {
  if (!std::isfinite(t)) throw std::invalid_argument("integrate: t must be finite (seconds)");
  if (t < sim.t()) throw std::invalid_argument("integrate: t = " + std::to_string(t) + " s lies before the simulation's time " + std::to_string(sim.t()) + " s");
  run_cancellable([&](const cancellation& cancel) {
    const long target = static_cast<long>(std::floor(t / sim.h() + 1e-9));
    sim.advance(target - sim.steps(), {}, {}, [&] { return cancel.requested(); });
  });
}

}  // namespace

void bind_binary_simulation(py::module_& m) {
  py::class_<runs::binary_simulation, std::shared_ptr<runs::binary_simulation>>(
      m, "BinarySimulation", "The full two-body problem held by the user: integrate(t) continues to the absolute time t (s) in whole steps")
      .def("integrate", &integrate_to, py::arg("t"), "Steps on to the absolute time t in seconds (the steps whose end is at or before t)")
      .def("step", [](runs::binary_simulation& s) { s.step(); }, "One step")
      .def_property_readonly("t", &runs::binary_simulation::t, "the time, s (steps × h)")
      .def_property_readonly("h", &runs::binary_simulation::h, "the step, s")
      .def_property_readonly("steps", &runs::binary_simulation::steps, "the steps taken")
      .def_property_readonly("r", [](const runs::binary_simulation& s) { return state_array(s.state().r); }, "x2 - x1, km, inertial")
      .def_property_readonly("v", [](const runs::binary_simulation& s) { return state_array(s.state().v); }, "km/s")
      .def_property_readonly("Q1", [](const runs::binary_simulation& s) { return matrix(s.state().body[0].Q.a); }, "columns the primary's axes")
      .def_property_readonly("Q2", [](const runs::binary_simulation& s) { return matrix(s.state().body[1].Q.a); }, "columns the secondary's axes")
      .def_property_readonly("omega1", [](const runs::binary_simulation& s) { return state_array(models::angular_velocity(s.system().moments(0), s.state().body[0].G)); },
                             "rad/s, body frame")
      .def_property_readonly("omega2", [](const runs::binary_simulation& s) { return state_array(models::angular_velocity(s.system().moments(1), s.state().body[1].G)); },
                             "rad/s, body frame")
      .def_property_readonly("energy", &runs::binary_simulation::energy, "kg km2 s-2 (with the added terms' potentials at t)")
      .def_property_readonly("osculating", [](const runs::binary_simulation& s) {
        const auto o = runs::osculating_elements(s.state(), s.system().G() * s.system().total_mass());
        py::dict d;
        d["a_km"] = o.a_km, d["e"] = o.e, d["i_deg"] = o.i_deg, d["period_h"] = o.period_h;
        return d;
      }, "the mutual orbit's osculating elements now: a_km, e, i_deg, period_h")
      .def_property_readonly("libration_angle", [](const runs::binary_simulation& s) { return runs::libration_angle(s.state()); },
                             "the secondary's long axis against the line of centres now, rad")
      .def_property_readonly("spin_periods_h", [](const runs::binary_simulation& s) {
        return py::make_tuple(runs::spin_period_h(s.system(), s.state(), 0), runs::spin_period_h(s.system(), s.state(), 1));
      }, "both bodies' spin periods now, hours")
      .def_property_readonly("angular_momentum", [](const runs::binary_simulation& s) { return state_array(s.system().angular_momentum(s.state())); },
                             "r x mu v + Q1 G1 + Q2 G2, kg km2 s-1, inertial")
      .def("to_dict", [](const runs::binary_simulation& s) { return py::module_::import("json").attr("loads")(runs::binary_json(s.result()).dump()); },
           "The run so far as `rotlie binary --json` writes it (T the time reached)")
      .def("__copy__", [](const runs::binary_simulation& s) { return std::make_shared<runs::binary_simulation>(s); })
      .def("__deepcopy__", [](const runs::binary_simulation& s, const py::dict&) { return std::make_shared<runs::binary_simulation>(s); }, py::arg("memo"))
      .def("__repr__", [](const runs::binary_simulation& s) {
        return "<BinarySimulation " + s.setup().method.name + ", t = " + std::to_string(s.t()) + " s, " + std::to_string(s.steps()) + " steps>";
      });
  m.def("_binary_simulation_keywords", [] { return keyword_table(true); }, "binary_simulation's keywords: (name, annotation, default, help)");
  py::options options;
  options.disable_function_signatures();  // the signature help() shows is rotlie.binary_simulation's (python/rotlie/_typed.py)
  m.def("binary_simulation", &binary_simulation,
        ("The full two-body problem as a simulation you hold: rotlie.binary's keywords but T, every and observe (h required).\n"
         "sim.integrate(t) steps on to the absolute time t; integrate(T/2) then integrate(T) equals one run to T bit for bit.\n"
         "copy.copy(sim) saves it whole. Ctrl-C stops integrate at a step's end, the state kept.\n\nKeywords:" +
         keywords_doc(true))
            .c_str());
}

}  // namespace rotlie::python
