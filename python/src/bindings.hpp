#pragma once
// The pieces of the extension rotlie._rotlie, one function per source file. Bodies cross the
// boundary as exact text "I1,I2,I3" (the Python layer's Body.text), schemes as Scheme objects.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::python {

/// A scheme table as Python sees it: the table, its cost, and ‖H_R5‖ when it was solved here.
struct scheme_object {
  schemes::scheme_table table;
  std::optional<double> remainder_norm;
  std::string stage_name_of(std::size_t i) const { return table.stages.at(i).name; }
};

// Every part of the module, in binding order: python/src/NAME.cpp defines bind_NAME (scheme_objects.cpp
// binds `schemes`). A new Python call is its file and its name on this line.
#define ROTLIE_PYTHON_PARTS(X) X(errors) X(bodies) X(schemes) X(flows) X(json_commands) X(md) X(md_simulation) X(remainder) X(spin) X(spin_simulation) X(binary) X(binary_simulation)

#define ROTLIE_PYTHON_DECLARE_PART(name) void bind_##name(pybind11::module_& m);
ROTLIE_PYTHON_PARTS(ROTLIE_PYTHON_DECLARE_PART)
#undef ROTLIE_PYTHON_DECLARE_PART

}  // namespace rotlie::python
