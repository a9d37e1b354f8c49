#include "rotlie/runs/sixth_io.hpp"

#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {

nlohmann::ordered_json sixth_json(const runs::sixth_search_result& r, const lie::moments_of_inertia& body,
                                  const std::string& split) {
  nlohmann::ordered_json tables = nlohmann::ordered_json::array();
  for (const auto& t : r.best) {
    if (!t.polished) {
      tables.push_back({{"word", t.word}, {"permutation", t.permutation}, {"remainder7", t.remainder7}, {"polished", false},
                        {"why", t.why}, {"jacobian_condition_ratio", t.jacobian_ratio},
                        {"smallest_free_coefficient", t.smallest_free_coefficient}});
      continue;
    }
    tables.push_back({{"name", t.name}, {"word", t.word}, {"permutation", t.permutation}, {"remainder7", t.remainder7},
                      {"remainder7_at_equal_cost", t.remainder7_at_equal_cost}, {"cost", t.cost},
                      {"max_coefficient", t.max_coefficient}, {"hits", t.hits}, {"residual", t.residual},
                      {"jacobian_condition_ratio", t.jacobian_ratio}, {"polished", true}, {"file", t.file}});
  }
  const auto& stats = r.stats;
  nlohmann::ordered_json j;
  j["inertia"] = lie::inertia_text(body);
  j["split"] = split;
  j["systems"] = stats.systems;
  j["systems_with_roots"] = stats.with_roots;
  j["starts"] = stats.starts;
  j["converged"] = stats.converged;
  j["roots"] = stats.roots;
  j["roots_hit_once"] = stats.hit_once;
  j["roots_hit_twice"] = stats.hit_twice;
  j["roots_hit_more"] = stats.hit_more;
  j["good_turing_unseen"] = stats.unseen;
  j["chao1_roots"] = stats.chao1;
  j["cpu_seconds"] = r.cpu_seconds;
  j["best"] = tables;
  return j;
}

nlohmann::ordered_json sixth_references_json() {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& name : schemes::reference_sixth_order_scheme_names()) {
    const auto t = *schemes::reference_scheme(name);
    j.push_back({{"name", name}, {"order", t.order}, {"stages", t.stages.size()}, {"cost", schemes::cost_in_rotations(t)},
                 {"source", t.source}});
  }
  return j;
}

}  // namespace rotlie::runs
