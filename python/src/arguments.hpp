#pragma once
// What the typed calls (spin.cpp, binary.cpp) share: numbers and every=K as the command line reads
// them, TypeErrors as Python raises them, the results' arrays and common properties.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace rotlie::python {

namespace py = pybind11;

// A TypeError as Python raises it (the module's translator would make a C++ exception a RuntimeError).
[[noreturn]] inline void type_error(const std::string& message) {
  PyErr_SetString(PyExc_TypeError, message.c_str());
  throw py::error_already_set();
}

// A number as the command line reads it: str, int, float or Fraction, as str() writes it; NumPy's
// scalars (any numbers.Integral or numbers.Real) as the int or float they hold, so that str() writes
// them exactly (repr of a float round-trips).
inline std::string number_argument(const py::handle& value, const char* what) {
  if (py::isinstance<py::bool_>(value) || PyComplex_Check(value.ptr()))
    type_error(std::string(what) + " must be a real number, a Fraction or its text");
  const auto fractions = py::module_::import("fractions");
  if (py::isinstance<py::str>(value) || py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
      py::isinstance(value, fractions.attr("Fraction")))
    return py::str(value);
  const auto numbers = py::module_::import("numbers");
  if (py::isinstance(value, numbers.attr("Integral"))) return py::str(py::int_(py::reinterpret_borrow<py::object>(value)));
  if (py::isinstance(value, numbers.attr("Real"))) return py::str(py::float_(py::reinterpret_borrow<py::object>(value)));
  type_error(std::string(what) + " must be a real number, a Fraction or its text, got " + std::string(py::str(value.get_type().attr("__name__"))));
}

// An integer argument: int or any numbers.Integral (NumPy's), never a bool or a float truncated to one.
inline bool is_integer_argument(const py::handle& value) {
  return !py::isinstance<py::bool_>(value) && py::isinstance(value, py::module_::import("numbers").attr("Integral"));
}

// every=K: None (no trajectory) or an integer, never a float truncated to one.
inline std::string every_argument(const py::handle& every) {
  if (every.is_none()) return "0";
  if (!is_integer_argument(every)) type_error("every must be an integer or None");
  return py::str(py::int_(py::reinterpret_borrow<py::object>(every)));
}

// A body as `rotlie spin --body` takes it: a name or "A,B,C" as text, a Body, or three moments.
inline std::string spin_body_argument(const py::handle& body) {
  if (py::isinstance<py::str>(body)) return py::str(body);
  const py::object moments = py::hasattr(body, "moments") ? py::object(body.attr("moments")) : py::reinterpret_borrow<py::object>(body);
  std::string text;
  for (const auto& m : py::iter(moments)) text += (text.empty() ? "" : ",") + number_argument(m, "a moment of body");
  return text;
}

inline py::array_t<double> vector_array(const std::vector<double>& v) { return py::array_t<double>(py::ssize_t(v.size()), v.data()); }

// Rows of N fixed-size arrays as one array of shape (N, tail...).
template <std::size_t n>
py::array_t<double> rows_array(const std::vector<std::array<double, n>>& rows, std::vector<py::ssize_t> tail) {
  tail.insert(tail.begin(), py::ssize_t(rows.size()));
  py::array_t<double> a(tail);
  for (std::size_t k = 0; k < rows.size(); ++k) std::copy(rows[k].begin(), rows[k].end(), a.mutable_data() + n * k);
  return a;
}

inline py::array_t<double> matrix(const std::array<double, 9>& Q) {
  py::array_t<double> a({3, 3});
  std::copy(Q.begin(), Q.end(), a.mutable_data());
  return a;
}

// The properties every scene result shares (spin, binary: an object with `result` and its JSON text
// `json`): the stepping fields, cpu_s, the stability flags and to_dict(); `h_doc` gives the step's unit.
template <class Object, class Class>
void def_run_properties(Class& c, const char* h_doc, const char* command) {
  c.def_property_readonly("integrator", [](const Object& o) { return o.result.setup.method.name; })
      .def_property_readonly("h", [](const Object& o) { return o.result.setup.h; }, h_doc)
      .def_property_readonly("T", [](const Object& o) { return o.result.setup.T; })
      .def_property_readonly("steps", [](const Object& o) { return o.result.setup.steps; })
      .def_property_readonly("evaluations", [](const Object& o) { return o.result.evaluations; })
      .def_property_readonly("cpu_s", [](const Object& o) { return o.result.cpu_s; })
      .def_property_readonly("unstable", [](const Object& o) { return o.result.check.unstable; })
      .def_property_readonly("round_off_floor", [](const Object& o) { return o.result.check.round_off_floor; })
      .def("to_dict", [](const Object& o) { return py::module_::import("json").attr("loads")(o.json); },
           (std::string("the object `rotlie ") + command + " --json` prints").c_str());
}

}  // namespace rotlie::python
