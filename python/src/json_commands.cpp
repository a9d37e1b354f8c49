// The commands whose result is the command line's JSON, returned as its text (the Python layer
// reads it with json.loads): best, bch and map_line, computed by the same floor calls as `rotlie
// best --json`, `rotlie bch --json` and one body line of `rotlie map`.
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/bch/free_bch.hpp"
#include "rotlie/runs/best_io.hpp"
#include "rotlie/runs/best_for_body.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/solver/body_grid.hpp"

namespace rotlie::python {
namespace {

std::string best(const std::string& body, bool analytic_only) {
  auto out = std::make_shared<std::string>();
  run_symbolic([=] { *out = runs::best_json(runs::best_for_body(runs::best_body(body), analytic_only)).dump(); });
  return *out;
}

// {"series", "degree", "terms": [{"word", "coefficient"}]}: every Lyndon basis element of the series
// to the degree, with its exact coefficient (as `rotlie bch --json`).
std::string bch_series(const std::string& name, long degree) {
  auto out = std::make_shared<std::string>();
  run_symbolic([=] {
    const auto series = bch::parse_free_series(name);
    if (!series)
      throw runs::bad_input("unknown series '" + runs::one_line(name) + "' for --series (expected XY, XYX, SYM or XYZ)");
    const long d = runs::integer_in_range(std::to_string(degree), "--degree", 1, bch::max_series_degree(*series));
    const auto s = bch::compute_free_series(*series, static_cast<int>(d), {1, false});
    std::string text = "{\"series\":\"" + std::string(bch::series_name(*series)) + "\",\"degree\":" + std::to_string(d) +
                       ",\"terms\":[";
    for (std::size_t i = 0; i < s.size(); ++i)
      text += std::string(i ? "," : "") + "{\"word\":\"" + s.basis->foliage(i) + "\",\"coefficient\":\"" +
              s.coefficient_text(i) + "\"}";
    *out = text + "]}";
  });
  return *out;
}

// The map line of the body at grid indices (i, j) of the grid K: by the path `rotlie map` takes for
// the family (its row computed as the map computes it, so that the line is the map file's; for the
// screened path, the row's line before the map's neighbour check), or by the exact solver for that
// body alone.
std::string map_line(const std::string& family, long i, long j, long K, bool exact) {
  auto out = std::make_shared<std::string>();
  run_symbolic([=] {
    const auto& f = runs::family_to_map(family);
    const long k = runs::integer_in_range(std::to_string(K), "--grid", 2, solver::max_grid_divisions);
    runs::integer_in_range(std::to_string(i), "s·grid", 0, k);
    runs::integer_in_range(std::to_string(j), "t·grid", 0, k);
    if (solver::grid_point(static_cast<int>(k), static_cast<int>(i), static_cast<int>(j)).symmetric)
      throw runs::bad_input("the body at s, t is a symmetric top, which the maps leave out");
    std::vector<solver::grid_body> row;  // the map's bodies with this s, in the map's order
    for (const auto& g : solver::asymmetric_grid(static_cast<int>(k)))
      if (g.i == i) row.push_back(g);
    std::size_t at = 0;
    while (row[at].j != j) ++at;
    std::vector<char> done(row.size(), 1);  // the row is carried whole; only this body's line is written
    done[at] = 0;
    const auto lines = runs::map_row_lines(row, 0, row.size(), done, std::string(f.name),
                                           runs::map_method_asked(f, static_cast<int>(k), exact, false));
    if (lines.size() != 1) throw std::runtime_error("the map row gave no line for the body");
    *out = lines.front().second;
  });
  return *out;
}

}  // namespace

void bind_json_commands(pybind11::module_& m) {
  namespace py = pybind11;
  m.def("best", &best, py::arg("body"), py::arg("analytic_only"));
  m.def("bch", &bch_series, py::arg("series"), py::arg("degree"));
  m.def("map_line", &map_line, py::arg("family"), py::arg("i"), py::arg("j"), py::arg("grid"), py::arg("exact"));
}

}  // namespace rotlie::python
