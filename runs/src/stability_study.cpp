// The measurements of the report's section "Stability: where methods fail" (see stability_study.hpp).
#include "rotlie/runs/stability_study.hpp"

#include <stdexcept>

#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {

stability_study_result stability_study(bool quick, const std::function<void(const std::string&)>& progress) {
  stability_study_result out;
  out.total_time = quick ? 4 : 10;
  out.bodies = {{"water", "water molecule", "10220/29376,19187/29376,1", {}},
                {"near_symmetric", "near-symmetric body (I1 ≈ I2)", "1/2,501/1000,1", {}},
                {"near_flat", "near-flat body (I1 + I2 ≈ I3)", "1/5,8001/10000,1", {}}};
  const std::vector<std::string> reference_bases = {"ABCBA2",           "RSR2",           "ABCBA4-SS3-Yoshida",
                                                    "RSR4-SS3-Yoshida", "ABC4-S5-McLachlan", "RS4-S5-McLachlan"};
  for (auto& b : out.bodies) {
    if (progress) progress(b.title);
    const auto body = lie::parse_moments(b.inertia);
    const auto I = models::moments_from_text<double>(lie::inertia_text(body));
    std::vector<schemes::scheme_table> tables;
    const protocol_runner chooser(body, 3, 7, false);
    for (const auto& base : reference_bases) tables.push_back(*schemes::reference_scheme(chooser.best_permutation(base).name));
    // "best N": the N solution with the smallest analytic remainder for this body
    const auto n = solver::solve_dedicated(body, {"N1", "N2", "N3", "N4", "N5", "N6", "N7"}, bch::permutation_names(), 40);
    if (n.solutions.empty()) throw std::runtime_error("no N solution for the " + b.title);
    auto best_n = solver::scheme_table_of(n.solutions.front(), body);
    best_n.name = "best N: " + n.solutions.front().name();
    tables.push_back(best_n);
    if (b.key == "water") {
      auto p1 = scheme_named("P1:BAC:5", body);
      p1.name = "P1 BAC (5)";
      auto r4 = scheme_named("R:ABC:4", body);
      r4.name = "R ABC (4)";
      tables.push_back(p1), tables.push_back(r4);
    }
    models::body_state<double> initial;
    initial.G = {1, 1, 1};
    for (const auto& t : tables)
      b.rows.push_back({t.name, schemes::cost_in_rotations(t),
                        models::stability_scan<double>(t, I, initial, out.total_time, 1.0 / 32, 4, out.threshold)});
  }
  return out;
}

}  // namespace rotlie::runs
