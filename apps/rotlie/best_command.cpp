// rotlie best: for one body, the best N, R and P integrators by analytic remainder ‖H_R5‖ (eq. 64),
// the reference RS4 S5 McLachlan at its best permutation, and the gain predicted at equal cost — the
// map's answer (LV section 5) for a body off the grid. Every name is one that `integrate` accepts
// with the same --inertia.
#include <cmath>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/reports/map_io.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {
namespace {

std::string scientific(double x, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << std::scientific << x;
  return s.str();
}

}  // namespace

int run_best(const best_options& options) {
  if (options.inertia.empty()) throw usage_error("--inertia is required (I1,I2,I3, or water)");
  lie::moments_of_inertia body;
  try {
    body = lie::parse_moments(options.inertia);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what() + " (the body must lie in the set of rigid bodies, eq. 77)");
  }
  if (const auto symmetry = lie::symmetry_of(body); !symmetry.empty())
    throw usage_error("--inertia: a symmetric top (" + symmetry +
                      ") is outside the maps: its dedicated systems are singular; use `rotlie solve` for it");
  const auto [s, t] = solver::triangle_coordinates(body);

  std::vector<solver::map_point> points;
  {
    progress_line progress;  // cleared before the answer is printed
    for (const char* family : {"N", "R", "P"}) {
      progress.show(std::string("best: solving the ") + family + " family at every permutation");
      points.push_back(solver::compute_map_point(body, family));
    }
  }
  const auto& any = points.front();
  const std::string reference = std::string(solver::map_reference_scheme) + ":" + any.reference_permutation;
  // The recommendation: the largest predicted gain, or the reference when no family beats it.
  std::string recommended = reference;
  double best_gain = 1;
  for (const auto& p : points)
    if (p.ratio && *p.ratio > best_gain) best_gain = *p.ratio, recommended = solver::scheme_table_name(*p.best);

  if (options.json) {
    nlohmann::ordered_json j;
    j["inertia"] = {reports::fraction_text(body.I[0]), reports::fraction_text(body.I[1]), reports::fraction_text(body.I[2])};
    j["s"] = reports::fraction_text(s);
    j["t"] = reports::fraction_text(t);
    for (const auto& p : points) {
      nlohmann::ordered_json f;
      f["best"] = p.best ? nlohmann::ordered_json(solver::scheme_table_name(*p.best)) : nlohmann::ordered_json();
      f["remainder"] = p.best ? nlohmann::ordered_json(p.best->analytic_remainder) : nlohmann::ordered_json();
      f["cost"] = solver::family_cost(p.family);
      f["gain"] = p.ratio ? nlohmann::ordered_json(*p.ratio) : nlohmann::ordered_json();
      nlohmann::ordered_json singular = nlohmann::ordered_json::array();
      for (const auto& x : p.singular) singular.push_back(x.scheme + ":" + x.permutation);
      f["singular"] = singular;
      j[p.family] = f;
    }
    j["reference"] = {{"best", reference},
                      {"remainder", any.reference_remainder},
                      {"cost", solver::reference_cost(solver::map_reference_scheme)}};
    j["recommended"] = recommended;
    j["measure"] = "analytic remainder ||H_R5|| (eq. 64), gain = R_M / R_family x (C_M / C_family)^4";
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "Body " << options.inertia << ": in the triangle of LV section 5 at s = " << reports::fraction_text(s)
            << ", t = " << reports::fraction_text(t) << "\n"
            << "Ranked by the analytic remainder ||H_R5|| (eq. 64); gain = R_M / R x (C_M / C)^4 at equal cost "
               "(> 1: better than the reference).\n\n";
  for (const auto& p : points) {
    std::cout << "  best " << p.family << " (cost " << solver::family_cost(p.family) << "): ";
    if (!p.best) {
      std::cout << "none (no real solution at this body)\n";
      continue;
    }
    std::cout << solver::scheme_table_name(*p.best) << "  ||H_R5|| = " << scientific(p.best->analytic_remainder)
              << "  gain " << scientific(*p.ratio, 3) << "\n";
  }
  std::cout << "  reference (cost " << solver::reference_cost(solver::map_reference_scheme) << "): " << reference
            << "  ||H_R5|| = " << scientific(any.reference_remainder) << "\n\n"
            << "Recommended: " << recommended << "   (rotlie integrate --scheme " << recommended << " --inertia "
            << options.inertia << " --h …)\n";
  return 0;
}

}  // namespace rotlie::app
