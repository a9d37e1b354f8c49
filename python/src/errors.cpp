// Errors as Python sees them: bad arguments (runs::bad_input, any std::invalid_argument or
// std::domain_error) are ValueError, a failed run (std::runtime_error) is RuntimeError, each with
// the command line's one-line message.
#include <pybind11/pybind11.h>

#include <stdexcept>

#include "bindings.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::python {

void bind_errors(pybind11::module_& m) {
  (void)m;
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, runs::one_line(e.what()).c_str());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_ValueError, runs::one_line(e.what()).c_str());
    } catch (const std::runtime_error& e) {
      PyErr_SetString(PyExc_RuntimeError, runs::one_line(e.what()).c_str());
    }
  });
}

}  // namespace rotlie::python
