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

void bind_errors(pybind11::module_& m);
void bind_bodies(pybind11::module_& m);
void bind_schemes(pybind11::module_& m);
void bind_flows(pybind11::module_& m);
void bind_json_commands(pybind11::module_& m);
void bind_md(pybind11::module_& m);
void bind_remainder(pybind11::module_& m);
void bind_spin(pybind11::module_& m);

}  // namespace rotlie::python
