// Schemes: the Scheme class over a scheme table, scheme() by name, load_table() and Scheme.save(),
// and solve(): every real solution of a dedicated family for a body, ranked by ‖H_R5‖ as
// `rotlie solve` ranks them, each as a Scheme.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/solve_for_body.hpp"
#include "rotlie/runs/two_parameter_solve.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;

// Warnings collected off the GIL, issued as Python UserWarnings afterwards.
struct warnings {
  std::vector<std::string> lines;
  void issue() const {
    for (const auto& w : lines)
      if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 2) != 0) throw py::error_already_set();
  }
};

std::string read_table_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw runs::bad_input("no scheme-table file '" + path + "'");
  try {
    return runs::read_bounded_file(path, runs::max_table_bytes);  // the CLI's reader and bound
  } catch (const std::runtime_error& e) {
    throw runs::bad_input(e.what());
  }
}

scheme_object load_table(const std::string& path) {
  const std::string text = read_table_file(path);
  try {
    return {schemes::parse_scheme_table(text), std::nullopt};
  } catch (const std::invalid_argument& e) {
    throw runs::bad_input(path + ": " + e.what());
  }
}

scheme_object scheme_by_name(const std::string& name, const std::string& body, bool force) {
  if (body.empty()) {
    if (name.empty()) throw runs::bad_input("--scheme must not be empty");
    try {
      if (auto t = schemes::reference_scheme(name)) return {*t, std::nullopt};
    } catch (const std::invalid_argument& e) {
      throw runs::bad_input(std::string("--scheme: ") + e.what());
    }
    if (std::filesystem::exists(name)) return load_table(name);
    throw runs::bad_input("--scheme: '" + name +
                          "' is not a reference scheme: SCHEME:PERM:LABEL is solved for a body (give body=...)");
  }
  auto out = std::make_shared<scheme_object>();
  auto sink = std::make_shared<warnings>();
  run_symbolic([name, body, force, out, sink] {
    const auto moments = runs::numeric_body(body);
    out->table = runs::scheme_named(name, moments,
                                    force ? runs::foreign_table::use_with_warning : runs::foreign_table::refuse_unless_forced,
                                    [sink](const std::string& w) { sink->lines.push_back(w); });
  });
  sink->issue();
  return *out;
}

// Q, QRS: every searched system whose best minimum was polished, ranked as `rotlie solve` ranks them.
std::vector<scheme_object> solve_two_parameter(const runs::two_parameter_inputs& inputs) {
  const auto solved = runs::solve_two_parameter(inputs);
  std::vector<scheme_object> out;
  for (const auto& e : solved.result.entries)
    if (e.polished)
      out.push_back({schemes::parse_scheme_table(solved.table_text(e, "rotlie.solve(family=\"" + inputs.family + "\")")),
                     e.best.remainder});
  return out;
}

std::vector<scheme_object> solve(const std::string& body, const std::string& family, const std::string& perm,
                                 const std::string& scheme, long digits, const std::string& starts, const std::string& seed) {
  auto out = std::make_shared<std::vector<scheme_object>>();
  auto sink = std::make_shared<warnings>();
  run_symbolic([=] {
    const auto& f = runs::family_to_solve(family);
    if (f.kind == bch::family_kind::two_free_parameters) {
      *out = solve_two_parameter({family, scheme, perm, body, std::to_string(digits), starts.empty() ? "40" : starts,
                                  seed.empty() ? "1" : seed});
      return;
    }
    if (!starts.empty() || !seed.empty())
      throw runs::bad_input("--starts and --seed apply to the families of two free parameters (Q, QRS), not " + family);
    runs::integer_in_range(std::to_string(digits), "--digits", 10, runs::max_solve_digits);  // before the narrowing
    const auto solved = runs::solve_for_body({family, scheme, perm, body, static_cast<int>(digits)});
    sink->lines.insert(sink->lines.end(), solved.warnings.begin(), solved.warnings.end());
    const auto& result = solved.result;
    const auto& moments = solved.body;
    for (const auto& s : result.solutions)
      out->push_back({solver::scheme_table_of(s, moments, static_cast<int>(digits)), s.analytic_remainder});
  });
  sink->issue();
  return std::move(*out);
}

std::string split_text(const schemes::scheme_table& t) { return schemes::split_name(t.splitting); }

py::array_t<double> coefficients(const scheme_object& s) {
  py::array_t<double> a(static_cast<py::ssize_t>(s.table.stages.size()));
  auto v = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < s.table.stages.size(); ++i)
    v(static_cast<py::ssize_t>(i)) = std::strtod(s.table.stages[i].value.c_str(), nullptr);
  return a;
}

}  // namespace

void bind_schemes(py::module_& m) {
  py::class_<scheme_object>(m, "Scheme", "A splitting scheme: a scheme table (docs/scheme_table_format.md).")
      .def_property_readonly("name", [](const scheme_object& s) { return s.table.name; })
      .def_property_readonly("splitting", [](const scheme_object& s) { return split_text(s.table); })
      .def_property_readonly("word", [](const scheme_object& s) { return s.table.word; })
      .def_property_readonly("permutation", [](const scheme_object& s) { return s.table.permutation; })
      .def_property_readonly("order", [](const scheme_object& s) { return s.table.order; })
      .def_property_readonly("symmetric", [](const scheme_object& s) { return s.table.symmetric; })
      .def_property_readonly("inertia", [](const scheme_object& s) { return s.table.inertia; })
      .def_property_readonly("source", [](const scheme_object& s) { return s.table.source; })
      .def_property_readonly("cost", [](const scheme_object& s) { return schemes::cost_in_rotations(s.table); })
      .def_property_readonly("remainder_norm", [](const scheme_object& s) { return s.remainder_norm; })
      .def_property_readonly("stages",
                             [](const scheme_object& s) {
                               std::vector<std::pair<std::string, std::string>> out;
                               for (const auto& st : s.table.stages) out.emplace_back(std::string(1, st.part), st.value);
                               return out;
                             })
      .def_property_readonly("stage_names",
                             [](const scheme_object& s) {
                               std::vector<std::string> out;
                               for (const auto& st : s.table.stages) out.push_back(st.name);
                               return out;
                             })
      .def_property_readonly("coefficients", &coefficients)
      .def_property_readonly("text", [](const scheme_object& s) { return schemes::format_scheme_table(s.table); })
      .def(
          "save",
          [](const scheme_object& s, const std::string& path) {
            const std::string text = schemes::format_scheme_table(s.table);
            py::gil_scoped_release nogil;
            runs::write_file_atomically(path, text);
          },
          py::arg("path"))
      .def("__eq__", [](const scheme_object& a, const scheme_object& b) { return a.table == b.table; })
      .def("__repr__", [](const scheme_object& s) {
        return "<rotlie.Scheme " + s.table.name + ": " + split_text(s.table) + " " + s.table.word + ", order " +
               std::to_string(s.table.order) + ">";
      });
  m.def("load_table", &load_table, py::arg("path"));
  m.def("scheme", &scheme_by_name, py::arg("name"), py::arg("body"), py::arg("force"));
  m.def("solve", &solve, py::arg("body"), py::arg("family"), py::arg("perm"), py::arg("scheme"), py::arg("digits"),
        py::arg("starts"), py::arg("seed"));
}

}  // namespace rotlie::python
