#pragma once
// rotlie.binary's and rotlie.binary_simulation's keywords as the floor's request (runs::binary_request):
// numbers as the command line reads them, and each registered force term (runs/binary_terms.hpp) by
// its name: a sequence of numbers or its text "a,b,…".
#include <pybind11/pybind11.h>

#include <string>

#include "arguments.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_terms.hpp"

namespace rotlie::python {

// One value or a sequence, as the command line's "A" or "A,B,…".
inline std::string numbers_argument(const py::handle& value, const char* what) {
  if (value.is_none()) return "";
  if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    std::string text;
    for (const auto& x : value) text += (text.empty() ? "" : ",") + number_argument(x, what);
    return text;
  }
  return number_argument(value, what);
}

inline std::string optional_number(const py::handle& value, const char* what) { return value.is_none() ? "" : number_argument(value, what); }

inline std::string optional_text(const py::handle& value, const char* what) {
  if (value.is_none()) return "";
  if (!py::isinstance<py::str>(value)) type_error(std::string(what) + " must be text or None");
  return py::str(value);
}

/// The request of everything but T and every; `terms` the keywords beyond the named ones.
inline runs::binary_request binary_keywords(const py::object& system, const py::object& primary, const py::object& secondary, const py::object& density,
                                            const py::object& mass, int order, const py::object& G, const py::object& separation,
                                            const py::object& primary_period, const py::object& state, const std::string& integrator,
                                            const py::object& h, const py::object& impulse, bool force, const py::dict& terms,
                                            const char* function) {
  runs::binary_request q;
  q.system = optional_text(system, "system"), q.primary = optional_text(primary, "primary"), q.secondary = optional_text(secondary, "secondary");
  q.density = numbers_argument(density, "density"), q.mass = numbers_argument(mass, "mass"), q.order = std::to_string(order);
  q.G = number_argument(G, "G"), q.separation = optional_number(separation, "separation");
  q.primary_period = optional_number(primary_period, "primary_period");
  if (py::isinstance<py::dict>(state))
    q.state_text = py::str(py::module_::import("json").attr("dumps")(state));
  else
    q.state_file = optional_text(state, "state (a file's path or a dict)");
  q.integrator = integrator, q.h = optional_number(h, "h"), q.force = force, q.impulse = optional_text(impulse, "impulse");
  for (const auto& [key, value] : terms) {
    const std::string name = py::str(key);
    if (!runs::binary_term_named(name)) type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
    if (!value.is_none()) q.terms[name] = numbers_argument(value, name.c_str());
  }
  return q;
}

/// The docstring's lines for the registered terms.
inline std::string term_keywords_doc() {
  std::string text;
  for (const auto& term : runs::binary_terms()) text += "\n" + term.name + ": " + term.summary + " (" + runs::term_syntax(term) + "), a sequence or its text";
  return text;
}

}  // namespace rotlie::python
