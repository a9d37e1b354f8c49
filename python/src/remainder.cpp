// remainder: the modified Hamiltonian H_R2 … H_RK of a scheme (bch::compute_remainder), as the JSON
// and the LaTeX of `rotlie remainder` (reports/remainder_io.hpp), checked by runs/remainder_run as the CLI is.
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/runs/remainder_io.hpp"
#include "rotlie/runs/remainder_run.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::python {
namespace {

using coefficient_texts = std::vector<runs::coefficient_text>;

// {"json": the command's JSON text, "latex": its --latex text}
std::pair<std::string, std::string> remainder(const std::string& scheme, long order, const std::string& body,
                                              const std::string& perm, const std::string& split,
                                              const coefficient_texts& coeffs) {
  auto out = std::make_shared<std::pair<std::string, std::string>>();
  run_symbolic([=] {
    const auto result = runs::remainder_run({scheme, split, perm, std::to_string(order), body, coeffs});
    *out = {runs::remainder_json(result).dump(), runs::remainder_latex(result)};
  });
  return *out;
}

// The free coefficients of a paper's named scheme, or of a word in a splitting (ABC or RS): those
// a solved table's values are given for.
std::vector<std::string> free_coefficients(const std::string& name, const std::string& perm, const std::string& split) {
  auto out = std::make_shared<std::vector<std::string>>();
  run_symbolic([=] {
    if (const auto named = bch::find_named_scheme(name)) {
      *out = bch::layout_scheme(named->word, named->split, perm).free_coefficients;
      return;
    }
    if (split != "ABC" && split != "RS") throw runs::bad_input("--scheme: unknown scheme name '" + name + "'");
    try {
      *out = bch::layout_scheme(name, split == "ABC" ? bch::splitting::abc : bch::splitting::rs, perm).free_coefficients;
    } catch (const std::invalid_argument& e) {
      throw runs::bad_input(std::string("--scheme: ") + e.what());
    }
  });
  return *out;
}

}  // namespace

void bind_remainder(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("remainder", &remainder, py::arg("scheme"), py::arg("order"), py::arg("body"), py::arg("perm"), py::arg("split"),
        py::arg("coeffs"));
  m.def("free_coefficients", &free_coefficients, py::arg("scheme"), py::arg("perm"), py::arg("split"));
}

}  // namespace rotlie::python
