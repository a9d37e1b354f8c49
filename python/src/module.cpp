// rotlie._rotlie: the compiled half of the Python package (python/rotlie/__init__.py is the other).
#include "bindings.hpp"

PYBIND11_MODULE(_rotlie, m) {
  m.doc() = "rotlie's library floor and numeric core (use the package rotlie, not this module)";
#define ROTLIE_PYTHON_BIND_PART(name) rotlie::python::bind_##name(m);
  ROTLIE_PYTHON_PARTS(ROTLIE_PYTHON_BIND_PART)
#undef ROTLIE_PYTHON_BIND_PART
}
