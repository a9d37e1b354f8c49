// md_simulation: a scene of the registry held (runs::md_simulation) as rotlie.md_simulation(...),
// rotlie.md's options but T and every; integrate(t) to an absolute time in ps.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <string>

#include "arguments.hpp"
#include "bindings.hpp"
#include "held_simulation.hpp"
#include "interruption.hpp"
#include "rotlie/runs/md_simulation.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;
using held_md = held<runs::md_simulation>;

std::unique_ptr<held_md> md_simulation(const std::string& scene, const std::string& integrator, const std::string& h,
                                       const std::map<std::string, std::string>& options) {
  const runs::scene_request request{scene, integrator, h, options, {}};
  auto out = std::make_shared<std::unique_ptr<held_md>>();
  run_symbolic([request, out] {  // a rotor SCHEME:PERM:LABEL is solved symbolically
    *out = std::make_unique<held_md>(held_md{runs::md_simulation(request)});
  });
  return std::move(*out);
}

// Every body of every system, one row each (run-major), a field of shape `tail` taken by `get`.
template <class Get>
py::array_t<double> body_rows(const runs::md_simulation& s, std::vector<py::ssize_t> tail, std::size_t n, Get get) {
  tail.insert(tail.begin(), py::ssize_t(s.systems() * s.bodies()));
  py::array_t<double> a(tail);
  double* out = a.mutable_data();
  for (long sys = 0; sys < s.systems(); ++sys)
    for (long i = 0; i < s.bodies(); ++i, out += n) {
      const auto b = s.body(sys, i);
      const double* v = get(b);
      std::copy(v, v + n, out);
    }
  return a;
}

// One value per system.
template <class Get>
py::array_t<double> system_values(const runs::md_simulation& s, Get get) {
  py::array_t<double> a(py::ssize_t(s.systems()));
  for (long sys = 0; sys < s.systems(); ++sys) a.mutable_data()[sys] = get(sys);
  return a;
}

}  // namespace

void bind_md_simulation(py::module_& m) {
  py::class_<held_md>(m, "MdSimulation", "A run of an md scene held between calls (rotlie.md_simulation)")
      .def("integrate", &integrate_held<runs::md_simulation>, py::arg("t"),
           "To the absolute time t (ps) in whole steps h (the last step's end at most t, round-off aside); "
           "a t before the current step raises ValueError")
      .def("step", [](held_md& s) { s.sim.step(); }, "one step h of every system")
      .def_property_readonly("t", [](const held_md& s) { return s.sim.t(); }, "steps × h, ps")
      .def_property_readonly("steps", [](const held_md& s) { return s.sim.steps(); })
      .def_property_readonly("h", [](const held_md& s) { return s.sim.setup().h_fs; }, "the step, fs")
      .def_property_readonly("scene", [](const held_md& s) { return s.sim.setup().scene; })
      .def_property_readonly("integrator", [](const held_md& s) { return s.sim.setup().integrator; })
      .def_property_readonly("scalar", [](const held_md& s) { return s.sim.setup().scalar; })
      .def_property_readonly("runs", [](const held_md& s) { return s.sim.setup().runs; })
      .def_property_readonly("seed", [](const held_md& s) { return s.sim.setup().seed; })
      .def_property_readonly("q", [](const held_md& s) { return body_rows(s.sim, {3}, 3, [](const runs::md_body& b) { return b.q.data(); }); },
                             "positions (Å), shape (N, 3): one row per body of each run")
      .def_property_readonly("p", [](const held_md& s) { return body_rows(s.sim, {3}, 3, [](const runs::md_body& b) { return b.p.data(); }); },
                             "momenta (g/mol·Å/fs), shape (N, 3)")
      .def_property_readonly("Q", [](const held_md& s) { return body_rows(s.sim, {3, 3}, 9, [](const runs::md_body& b) { return b.Q.a.data(); }); },
                             "attitudes (body → lab), shape (N, 3, 3)")
      .def_property_readonly("G", [](const held_md& s) { return body_rows(s.sim, {3}, 3, [](const runs::md_body& b) { return b.G.data(); }); },
                             "body-frame angular momenta, shape (N, 3)")
      .def_property_readonly("energy", [](const held_md& s) { return system_values(s.sim, [&](long i) { return s.sim.energy(i); }); },
                             "kinetic + potential energy (kcal/mol) of each run, shape (runs,)")
      .def_property_readonly("potential", [](const held_md& s) { return system_values(s.sim, [&](long i) { return s.sim.potential(i); }); },
                             "potential energy (kcal/mol) of each run, shape (runs,)")
      .def_property_readonly("evaluations", [](const held_md& s) { return s.sim.force_evaluations(); }, "force evaluations over the runs")
      .def("__repr__", [](const held_md& s) {
        return "<MdSimulation " + s.sim.setup().scene + " " + s.sim.setup().integrator + ", " + std::to_string(s.sim.systems()) +
               " run(s), step " + std::to_string(s.sim.steps()) + ">";
      });
  m.def("md_simulation", &md_simulation, py::arg("scene"), py::arg("integrator"), py::arg("h"), py::arg("options"));
}

}  // namespace rotlie::python
