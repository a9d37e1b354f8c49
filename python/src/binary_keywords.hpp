#pragma once
// rotlie.binary's and rotlie.binary_simulation's keywords as the floor's request: each field of
// runs/binary_fields.hpp by its name and kind, each registered force term (runs/binary_terms.hpp) by
// its name (a sequence of numbers or its text), numbers as the command line reads them. Unknown,
// misplaced or missing keywords raise TypeError as Python's own calls do.
#include <pybind11/pybind11.h>

#include <string>

#include "arguments.hpp"
#include "rotlie/runs/binary_fields.hpp"
#include "rotlie/runs/binary_terms.hpp"

namespace rotlie::python {

// One value or a sequence, as the command line's "A" or "A,B,…".
inline std::string numbers_argument(const py::handle& value, const char* what) {
  if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    std::string text;
    for (const auto& x : value) text += (text.empty() ? "" : ",") + number_argument(x, what);
    return text;
  }
  return number_argument(value, what);
}

// The fields of a start, as a state file holds them.
inline constexpr const char* state_keys[] = {"r", "v", "Q1", "Q2", "omega1", "omega2"};

// A result or a held simulation: it has every field of a start.
inline bool has_state_attributes(const py::handle& value) {
  for (const char* key : state_keys)
    if (!py::hasattr(value, key)) return false;
  return true;
}

// A start given as a dict or as an object with its fields, as JSON text: NumPy arrays and scalars as
// the lists and numbers they hold (tolist() keeps every double exactly).
inline std::string state_json(const py::handle& value) {
  py::dict fields;
  if (py::isinstance<py::dict>(value))
    fields = py::reinterpret_borrow<py::dict>(value);
  else
    for (const char* key : state_keys) fields[key] = value.attr(key);
  const auto plain = py::cpp_function([](const py::object& x) -> py::object {
    if (py::hasattr(x, "tolist")) return x.attr("tolist")();
    type_error("state: a value of type " + std::string(py::str(x.get_type().attr("__name__"))) + " is not a number or an array");
  });
  return py::str(py::module_::import("json").attr("dumps")(fields, py::arg("default") = plain, py::arg("allow_nan") = true));
}

inline std::string field_argument(const runs::binary_field& f, const py::handle& value) {
  using kind = runs::binary_field::kind;
  const char* name = f.name.c_str();
  switch (f.type) {
    case kind::number:
      return number_argument(value, name);
    case kind::numbers:
      return numbers_argument(value, name);
    case kind::integer:
      if (!is_integer_argument(value)) type_error(f.name + " must be an integer, got " + std::string(py::str(value.get_type().attr("__name__"))));
      return py::str(py::int_(py::reinterpret_borrow<py::object>(value)));
    case kind::state:
      if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__"))
        type_error(f.name + " must be a file's path (str or os.PathLike), a dict of r, v, Q1, Q2, omega1, omega2, or a result or simulation that has them, got " +
                   std::string(py::str(value.get_type().attr("__name__"))));
      return py::str(py::module_::import("os").attr("fspath")(value));
    case kind::text:
    case kind::flag:
      break;
  }
  if (!py::isinstance<py::str>(value)) type_error(f.name + " must be text, got " + std::string(py::str(value.get_type().attr("__name__"))));
  return py::str(value);
}

/// The request of `function`'s keywords; a held simulation takes no run-only field (T, every, observe).
inline runs::binary_request binary_keywords(const py::kwargs& keywords, const std::string& function, bool simulation) {
  runs::binary_request q;
  for (const auto& f : runs::binary_fields())  // Python's default where the command line requires the option
    if (f.cli_required && f.python_default.size() > 2 && f.python_default.front() == '\'') q.*f.text = f.python_default.substr(1, f.python_default.size() - 2);
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key);
    if (runs::binary_term_named(name)) {
      if (!value.is_none()) q.terms[name] = numbers_argument(value, name.c_str());
      continue;
    }
    const auto* f = runs::binary_field_named(name);
    if (!f || f->name != name) type_error(function + "() got an unexpected keyword argument '" + name + "'");
    if (simulation && f->run_only) type_error(function + "() takes no '" + name + "': a simulation runs as far as integrate(t) asks");
    if (value.is_none()) continue;
    if (f->type == runs::binary_field::kind::flag) {
      if (!py::isinstance<py::bool_>(value)) type_error(name + " must be True or False");
      q.*f->flag = value.cast<bool>();
    } else if (f->type == runs::binary_field::kind::state && (py::isinstance<py::dict>(value) || has_state_attributes(value))) {
      q.state_text = state_json(value);
    } else {
      q.*f->text = field_argument(*f, value);
    }
  }
  if (!simulation)
    for (const auto& f : runs::binary_fields())
      if (f.python_default.empty() && !keywords.contains(f.name)) type_error(function + "() missing required keyword argument: '" + f.name + "'");
  return q;
}

/// The docstring's keyword lines: the fields (a simulation's without the run-only ones), then the terms.
inline std::string keywords_doc(bool simulation) {
  std::string text;
  for (const auto& f : runs::binary_fields())
    if (!(simulation && f.run_only))
      text += "\n" + f.name + " (" + f.python_type + (f.python_default.empty() ? ", required" : ", default " + f.python_default) + "): " + f.help;
  for (const auto& term : runs::binary_terms()) text += "\n" + term.name + " (added force term, " + runs::term_syntax(term) + "): " + term.summary;
  return text;
}

/// (name, annotation, default as Python writes it or "" when required, help) of each keyword, for the signature.
inline py::list keyword_table(bool simulation) {
  py::list out;
  for (const auto& f : runs::binary_fields())
    if (!(simulation && f.run_only)) out.append(py::make_tuple(f.name, f.python_type, f.python_default, f.help));
  return out;
}

}  // namespace rotlie::python
