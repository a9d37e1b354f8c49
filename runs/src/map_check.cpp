#include "rotlie/runs/map_check.hpp"

#include <algorithm>
#include <optional>
#include <random>

#include "rotlie/runs/map_file.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {

map_check_result check_map_lines(const std::string& family, int K, std::vector<nlohmann::json> bodies, std::size_t count,
                                 std::uint64_t seed, const std::function<void(int, int)>& progress) {
  std::mt19937_64 random(seed);
  std::shuffle(bodies.begin(), bodies.end(), random);
  const std::size_t M = std::min(count, bodies.size());
  const auto name = [](const std::optional<solver::dedicated_solution>& s) {
    return s ? solver::scheme_table_name(*s) : std::string();
  };
  map_check_result out;
  for (std::size_t k = 0; k < M; ++k) {
    if (progress) progress(static_cast<int>(k), static_cast<int>(M));
    const auto& b = bodies[k];
    const auto ij = map_line_indices(b, K);
    if (!ij) throw std::runtime_error("a map line is not a body of its grid");
    const auto g = solver::grid_point(K, ij->first, ij->second);
    const auto exact = solver::compute_map_point(g.body, family, solver::map_digits);
    std::vector<std::string> differ;
    const auto best = b.contains("best") && b["best"].is_string() ? b["best"].get<std::string>() : std::string();
    if (best != name(exact.best)) differ.push_back("best " + best + " vs " + name(exact.best));
    if (b.value("reference", std::string()) != std::string(solver::map_reference_scheme) + ":" + exact.reference_permutation)
      differ.push_back("reference");
    if (b.contains("real_solutions") && b["real_solutions"].is_number() && b["real_solutions"].get<int>() != exact.real_solutions)
      differ.push_back("real solutions");
    for (std::size_t p = 0; p < exact.per_permutation.size(); ++p) {
      const auto& e = b.at("permutations").at(p);
      const auto& want = exact.per_permutation[p].best;
      if (e.contains("unconfirmed_best")) {
        ++out.unconfirmed;
        if (!want || e["unconfirmed_best"].get<std::string>() != want->scheme + ":" + want->permutation) ++out.unconfirmed_differ;
        continue;
      }
      const std::string file = e.at("best").is_null() ? std::string() : e.at("best").get<std::string>();
      if (file != name(want)) differ.push_back("best at " + exact.per_permutation[p].permutation);
    }
    ++out.checked;
    if (differ.empty()) continue;
    ++out.disagreements;
    std::string line = "s = " + b.at("s").get<std::string>() + ", t = " + b.at("t").get<std::string>() + ":";
    for (const auto& d : differ) line += " " + d + ";";
    out.differences.push_back(line);
  }
  return out;
}

}  // namespace rotlie::runs
