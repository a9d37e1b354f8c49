// Errors as Python sees them: bad arguments (runs::bad_input, any std::invalid_argument or
// std::domain_error) are ValueError, a failed run (std::runtime_error) is RuntimeError, each with
// the command line's one-line message, its options named as Python's keywords (--primary-period is
// primary_period).
#include <pybind11/pybind11.h>

#include <regex>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::python {

namespace {

std::string python_message(const char* what) {
  static const std::regex option("--([A-Za-z][A-Za-z0-9]*(-[A-Za-z0-9]+)*)");
  const std::string text = runs::one_line(what);
  std::string out;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), option), end; it != end; ++it) {
    out.append(last, (*it)[0].first);
    std::string name = (*it)[1].str();
    for (auto& c : name)
      if (c == '-') c = '_';
    out += name;
    last = (*it)[0].second;
  }
  return out.append(last, text.cend());
}

}  // namespace

void bind_errors(pybind11::module_& m) {
  (void)m;
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, python_message(e.what()).c_str());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_ValueError, python_message(e.what()).c_str());
    } catch (const std::runtime_error& e) {
      PyErr_SetString(PyExc_RuntimeError, python_message(e.what()).c_str());
    }
  });
}

}  // namespace rotlie::python
