// rotlie._rotlie: the compiled half of the Python package (python/rotlie/__init__.py is the other).
#include "bindings.hpp"

PYBIND11_MODULE(_rotlie, m) {
  m.doc() = "rotlie's library floor and numeric core (use the package rotlie, not this module)";
  rotlie::python::bind_errors(m);
  rotlie::python::bind_bodies(m);
  rotlie::python::bind_schemes(m);
  rotlie::python::bind_flows(m);
  rotlie::python::bind_json_commands(m);
  rotlie::python::bind_md(m);
  rotlie::python::bind_remainder(m);
  rotlie::python::bind_spin(m);
}
