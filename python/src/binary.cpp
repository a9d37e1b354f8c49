// binary: the full two-body problem (runs::binary_run, `rotlie binary`) as rotlie.binary(...) with typed
// keywords; its result a BinaryResult whose attributes are the JSON's fields (vectors and attitudes as
// arrays, the trajectory's samples as arrays) and whose to_dict() is `rotlie binary --json`'s object.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "arguments.hpp"
#include "binary_keywords.hpp"
#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/methods.hpp"

namespace rotlie::python {
namespace {

struct binary_trajectory {
  std::vector<double> t, energy;
  std::vector<std::array<double, 3>> r, v, omega1, omega2;
  std::vector<std::array<double, 9>> Q1, Q2;
  long every = 0;
};

struct binary_object {
  runs::binary_result result;
  binary_trajectory trajectory;
  std::string json;  ///< `rotlie binary --json`'s text
  py::object fields;  ///< the same, parsed once (read by the attributes)
};

std::array<double, 3> vec(const models::vec3<double>& x) { return {x[0], x[1], x[2]}; }

py::array_t<double> array3(const models::vec3<double>& x) { return py::array_t<double>(3, x.data()); }

binary_object binary(const py::kwargs& keywords) {
  const auto q = binary_keywords(keywords, "binary", false);
  auto out = std::make_shared<binary_object>();
  auto setup = std::make_shared<runs::binary_setup>();
  run_symbolic([q, setup] { *setup = runs::binary_setup_of(q); });  // a rotor SCHEME:PERM:LABEL is solved symbolically
  // the run itself stops on Ctrl-C within 64 steps
  run_cancellable([&](const cancellation& cancel) {
    const auto sys = setup->system_model();
    auto& tr = out->trajectory;
    tr.every = setup->every;
    out->result = runs::binary_run(
        *setup,
        [&](const runs::binary_sample& s) {
          tr.t.push_back(s.t), tr.energy.push_back(s.energy), tr.r.push_back(vec(s.x.r)), tr.v.push_back(vec(s.x.v));
          tr.Q1.push_back(s.x.body[0].Q.a), tr.Q2.push_back(s.x.body[1].Q.a);
          tr.omega1.push_back(vec(models::angular_velocity(sys.moments(0), s.x.body[0].G)));
          tr.omega2.push_back(vec(models::angular_velocity(sys.moments(1), s.x.body[1].G)));
        },
        {}, [&] { return cancel.requested(); });
    out->json = runs::binary_json(out->result).dump();
  });
  out->fields = py::module_::import("json").attr("loads")(out->json);
  for (const auto& w : out->result.check.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) != 0) throw py::error_already_set();
  return std::move(*out);
}

py::object field(const binary_object& b, const char* key) { return b.fields[key]; }

}  // namespace

void bind_binary(py::module_& m) {
  py::class_<binary_trajectory>(m, "BinaryTrajectory", "The state every K steps from the start, as arrays")
      .def_readonly("every", &binary_trajectory::every)
      .def_property_readonly("t", [](const binary_trajectory& s) { return vector_array(s.t); }, "times in s, shape (N,)")
      .def_property_readonly("r", [](const binary_trajectory& s) { return rows_array(s.r, {3}); }, "x2 - x1 in km, inertial, shape (N, 3)")
      .def_property_readonly("v", [](const binary_trajectory& s) { return rows_array(s.v, {3}); }, "its rate in km/s, shape (N, 3)")
      .def_property_readonly("Q1", [](const binary_trajectory& s) { return rows_array(s.Q1, {3, 3}); }, "the primary's attitudes, shape (N, 3, 3)")
      .def_property_readonly("Q2", [](const binary_trajectory& s) { return rows_array(s.Q2, {3, 3}); }, "the secondary's attitudes, shape (N, 3, 3)")
      .def_property_readonly("omega1", [](const binary_trajectory& s) { return rows_array(s.omega1, {3}); }, "rad/s, body frame, shape (N, 3)")
      .def_property_readonly("omega2", [](const binary_trajectory& s) { return rows_array(s.omega2, {3}); }, "rad/s, body frame, shape (N, 3)")
      .def_property_readonly("energy", [](const binary_trajectory& s) { return vector_array(s.energy); }, "kg km2 s-2, shape (N,)");
  py::class_<binary_object> result(m, "BinaryResult", "The result of rotlie.binary: the fields of `rotlie binary --json` as attributes");
  def_run_properties<binary_object>(result, "the step taken, s", "binary");
  result.def_property_readonly("system", [](const binary_object& b) { return field(b, "system"); })
      .def_property_readonly("order", [](const binary_object& b) { return b.result.setup.order; })
      .def_property_readonly("G", [](const binary_object& b) { return b.result.setup.G; })
      .def_property_readonly("masses", [](const binary_object& b) { return py::array(field(b, "masses")).attr("astype")("float64"); }, "kg, shape (2,)")
      .def_property_readonly("moments", [](const binary_object& b) { return py::array(field(b, "moments")).attr("astype")("float64"); },
                             "principal moments, kg km2, shape (2, 3)")
      .def_property_readonly("t", [](const binary_object& b) { return b.result.end.t; })
      .def_property_readonly("r", [](const binary_object& b) { return array3(b.result.end.x.r); }, "x2 - x1, km, inertial")
      .def_property_readonly("v", [](const binary_object& b) { return array3(b.result.end.x.v); }, "km/s")
      .def_property_readonly("Q1", [](const binary_object& b) { return matrix(b.result.end.x.body[0].Q.a); }, "columns the primary's axes")
      .def_property_readonly("Q2", [](const binary_object& b) { return matrix(b.result.end.x.body[1].Q.a); }, "columns the secondary's axes")
      .def_property_readonly("omega1", [](const binary_object& b) { return py::array(field(b, "omega1")).attr("astype")("float64"); }, "rad/s, body frame")
      .def_property_readonly("omega2", [](const binary_object& b) { return py::array(field(b, "omega2")).attr("astype")("float64"); }, "rad/s, body frame")
      .def_property_readonly("energy", [](const binary_object& b) { return b.result.end.energy; })
      .def_property_readonly("energy_start", [](const binary_object& b) { return field(b, "energy_start"); })
      .def_property_readonly("angular_momentum", [](const binary_object& b) { return array3(b.result.angular_momentum); })
      .def_property_readonly("inaccurate", [](const binary_object& b) { return b.result.check.inaccurate; },
                             "the error estimate beyond the accuracy asked for, or not to be had (docs/binary.md)")
      .def_property_readonly("error_estimate", [](const binary_object& b) { return field(b, "error_estimate"); },
                             "{position_rel, velocity_rel, attitude1_rad, attitude2_rad, order, observed_order, step_ratio, cpu_s}, or None")
      .def_property_readonly("max_rel_energy_error", [](const binary_object& b) { return b.result.check.max_rel_energy_error; })
      .def_property_readonly("max_rel_angular_momentum_error", [](const binary_object& b) { return b.result.check.max_rel_angular_momentum_error; })
      .def_property_readonly("mutual", [](const binary_object& b) { return field(b, "mutual"); }, "{U, F, M1, M2} at the final state")
      .def_property_readonly("observables", [](const binary_object& b) -> py::object {
        if (!b.result.observables) return py::none();
        return field(b, "observables");
      }, "with observe=True: orbit_period_h, libration_amplitude_deg, libration_mean_deg, libration_period_h, spin_periods_h, separation_km, osculating, euler_deg, spin_state")
      .def_property_readonly("terms", [](const binary_object& b) {
        py::dict out;
        for (const auto& term : b.result.setup.terms) out[py::str(term.first)] = field(b, term.first.c_str());
        return out;
      }, "each added force term's values at the final state, by name (as the JSON's fields)")
      .def_property_readonly("trajectory", [](const binary_object& b) -> py::object {
        if (b.trajectory.every <= 0) return py::none();
        return py::cast(b.trajectory);
      }, "the samples every K steps (every=K), or None")
      .def("__repr__", [](const binary_object& b) {
        return "<BinaryResult " + b.result.setup.method.name + ", order " + std::to_string(b.result.setup.order) + ", " +
               std::to_string(b.result.setup.steps) + " steps" + (b.result.check.unstable ? ", unstable>" : ">");
      });
  m.def("_binary_keywords", [] { return keyword_table(false); }, "binary's keywords: (name, annotation, default, help)");
  py::options options;
  options.disable_function_signatures();  // the signature help() shows is rotlie.binary's (python/rotlie/_typed.py)
  m.def("binary", &binary,
        ("Two rigid bodies in mutual gravity (the full two-body problem), as ``rotlie binary`` (docs/binary.md); units km, kg, s.\n"
         "Returns a BinaryResult: the JSON's fields as attributes (arrays as NumPy), trajectory (every=K), observables (observe=True),\n"
         "terms (each added force term's values at the end). An untrusted run (BinaryResult.unstable) also raises a UserWarning;\n"
         "bodies that touch raise RuntimeError.\n\nKeywords:" +
         keywords_doc(false))
            .c_str());
}

}  // namespace rotlie::python
