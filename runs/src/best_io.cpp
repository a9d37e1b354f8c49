#include "rotlie/runs/best_io.hpp"

#include "rotlie/runs/map_file.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {
namespace {

using json = nlohmann::ordered_json;

json measured_json(const runs::measured_family& m, const solver::map_point& p, const std::optional<runs::measured_reference>& rs4) {
  json mj;
  mj["best"] = m.candidates.empty() ? json() : json(m.candidates.front().name);
  mj["error"] = m.candidates.empty() ? json() : json(m.candidates.front().error);
  mj["gain"] = m.candidates.empty() || !rs4 ? json() : json(rs4->error / m.candidates.front().error);
  mj["analytic_best_error"] = p.best ? json(m.analytic_best_error) : json();
  mj["analytic_best_gain"] = p.best && rs4 ? json(rs4->error / m.analytic_best_error) : json();
  json all = json::array();
  for (const auto& c : m.candidates) all.push_back({{"name", c.name}, {"remainder", c.remainder}, {"error", c.error}});
  mj["candidates"] = all;
  return mj;
}

}  // namespace

nlohmann::ordered_json best_json(const runs::best_result& r) {
  json j;
  j["inertia"] = {runs::fraction_text(r.body.I[0]), runs::fraction_text(r.body.I[1]), runs::fraction_text(r.body.I[2])};
  j["s"] = runs::fraction_text(r.s);
  j["t"] = runs::fraction_text(r.t);
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const auto& p = r.points[k];
    json f;
    f["best"] = p.best ? json(solver::scheme_table_name(*p.best)) : json();
    f["remainder"] = p.best ? json(p.best->analytic_remainder) : json();
    f["cost"] = solver::family_cost(p.family);
    f["gain"] = p.ratio ? json(*p.ratio) : json();
    json singular = json::array();
    for (const auto& x : p.singular) singular.push_back(x.scheme + ":" + x.permutation);
    f["singular"] = singular;
    if (r.measured) f["measured"] = measured_json(r.measured_families[k], p, r.rs4);
    j[p.family] = f;
  }
  j["reference"] = {{"best", r.reference},
                    {"remainder", r.points.front().reference_remainder},
                    {"cost", solver::reference_cost(solver::map_reference_scheme)}};
  j["recommended"] = r.recommended;
  j["measure"] = "analytic remainder ||H_R5|| (eq. 64), gain = R_M / R_family x (C_M / C_family)^4";
  if (r.measured) {
    json refs = json::array();
    for (const auto& x : r.references) refs.push_back({{"name", x.name}, {"cost", x.cost}, {"order", x.order}, {"error", x.error}});
    j["reference_measured"] = {{"best", r.rs4->name}, {"error", r.rs4->error}};
    j["best_reference_measured"] = {{"best", r.best_reference->name}, {"error", r.best_reference->error}};
    j["references_measured"] = refs;
    j["recommended_measured"] = r.recommended_measured;
    j["measured_protocol"] =
        "LV section 4.1 in double: G(0) = (1,1,1), identity attitude, T = 1, mean R^9 attitude error over every "
        "step at h/C = 1/1980 (C in rotations per step); gain = error of RS4-S5-McLachlan at its best measured "
        "permutation / error";
  }
  j["cpu_seconds"] = r.cpu_seconds;
  return j;
}

}  // namespace rotlie::runs
