// remainder: the modified Hamiltonian H_R2 … H_RK of a scheme (bch::compute_remainder), as the JSON
// and the LaTeX of `rotlie remainder` (reports/remainder_io.hpp).
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/reports/remainder_io.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::python {
namespace {

using coefficient_texts = std::vector<std::pair<std::string, std::string>>;

// {"json": the command's JSON text, "latex": its --latex text}
std::pair<std::string, std::string> remainder(const std::string& scheme, long order, const std::string& body,
                                              const std::string& perm, const std::string& split,
                                              const coefficient_texts& coeffs) {
  auto out = std::make_shared<std::pair<std::string, std::string>>();
  run_symbolic([=] {
    bch::remainder_request request;
    request.scheme = scheme;
    if (!split.empty()) {
      if (split != "ABC" && split != "RS") throw runs::bad_input("--split must be ABC or RS, got '" + split + "'");
      request.split = split == "ABC" ? bch::splitting::abc : bch::splitting::rs;
    }
    request.permutation = perm;
    request.order = static_cast<int>(runs::integer_in_range(std::to_string(order), "--order", 1, bch::max_remainder_order));
    if (!body.empty()) request.inertia = runs::exact_body(body);
    for (const auto& [name, text] : coeffs) {
      const auto value = lie::parse_exact_number(text);
      if (!value) {
        const auto why = runs::why_not_a_number(text);
        throw runs::bad_input("--coeffs: " + name + " = '" + text + "' " + (why == "is not a number" ? "is not a finite number" : why));
      }
      for (const auto& [n, v] : request.coefficients)
        if (n == name) throw runs::bad_input("--coeffs: " + name + " is given twice");
      request.coefficients.emplace_back(name, *value);
    }
    bch::remainder_result result;
    try {
      result = bch::compute_remainder(request);
    } catch (const std::invalid_argument& e) {
      throw runs::bad_input(e.what());
    }
    *out = {reports::remainder_json(result).dump(), reports::remainder_latex(result)};
  });
  return *out;
}

// The free coefficients of a paper's named scheme (those a solved table's values are given for).
std::vector<std::string> free_coefficients(const std::string& name, const std::string& perm) {
  auto out = std::make_shared<std::vector<std::string>>();
  run_symbolic([=] {
    const auto named = bch::find_named_scheme(name);
    if (!named) throw runs::bad_input("--scheme: unknown scheme name '" + name + "'");
    *out = bch::layout_scheme(named->word, named->split, perm).free_coefficients;
  });
  return *out;
}

}  // namespace

void bind_remainder(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("remainder", &remainder, py::arg("scheme"), py::arg("order"), py::arg("body"), py::arg("perm"), py::arg("split"),
        py::arg("coeffs"));
  m.def("free_coefficients", &free_coefficients, py::arg("scheme"), py::arg("perm"));
}

}  // namespace rotlie::python
