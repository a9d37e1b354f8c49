// SPDX-License-Identifier: GPL-2.0-or-later
#include "map_choice.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/shipped_data.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::lammps {
namespace {

const std::array<const char*, 3> map_families = {"N", "R", "P"};

// Every body line starts with its s and t as written by runs::map_line: the key a line is found by,
// without parsing the other 39,799 lines of a map.
std::string line_key(std::pair<int, int> point) {
  const auto g = solver::grid_point(shipped_grid, point.first, point.second);
  return "{\"s\":\"" + runs::fraction_text(g.s) + "\",\"t\":\"" + runs::fraction_text(g.t) + "\"";
}

std::string key_of_line(const std::string& line) {
  const auto t = line.find("\"t\":\"");
  const auto end = t == std::string::npos ? t : line.find('"', t + 5);
  return end == std::string::npos ? std::string() : line.substr(0, end + 1);
}

// The reference at the body's best permutation (smallest ‖H_R5‖), as the maps choose it.
std::pair<std::string, double> reference_at(const lie::moments_of_inertia& body) {
  std::pair<std::string, double> best{"", 0};
  for (const auto& perm : bch::permutation_names()) {
    const double r = solver::reference_analytic_remainder(body, solver::map_reference_scheme, perm);
    if (best.first.empty() || r < best.second) best = {perm, r};
  }
  return best;
}

// The family member the maps' lines name where one beats the reference at equal cost (the largest
// predicted gain, as `rotlie best` recommends), as its line gives it: {family, SCHEME:PERM:LABEL}.
std::optional<std::pair<std::string, std::string>> map_winner(const std::vector<std::string>& lines) {
  std::optional<std::pair<std::string, std::string>> winner;
  double gain = 1;
  for (const auto& text : lines) {
    const auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.contains("ratio") || !j["ratio"].is_number() || !j["best"].is_string()) continue;
    if (j["ratio"].get<double>() > gain) gain = j["ratio"].get<double>(), winner = {j["family"].get<std::string>(), j["best"].get<std::string>()};
  }
  return winner;
}

}  // namespace

std::pair<int, int> nearest_grid_point(const std::array<double, 3>& I) {
  const double x1 = I[0] / I[2], x2 = I[1] / I[2];
  const double s = 2 * x2 - 1, t = s > 0 ? (x1 - (1 - x2)) / s : 0;
  const auto index = [](double x, int lo, int hi) {
    return std::clamp(static_cast<int>(std::lround(x * shipped_grid)), lo, hi);
  };
  // s = 0 and 1 (i = 0, K) and t = 1 (j = K) are symmetric tops: the maps have no line there
  return {index(s, 1, shipped_grid - 1), index(std::clamp(t, 0.0, 1.0), 0, shipped_grid - 1)};
}

bool shipped_maps_present() {
  return std::all_of(map_families.begin(), map_families.end(), [](const char* f) { return runs::shipped_map(f).has_value(); });
}

shipped_map_lines::shipped_map_lines(const std::vector<std::pair<int, int>>& points) {
  std::map<std::string, std::pair<int, int>> wanted;
  for (const auto& p : points) wanted.emplace(line_key(p), p);
  for (const char* family : map_families) {
    const auto file = runs::shipped_map(family);
    if (!file)
      throw std::runtime_error(std::string("the shipped map maps-K200/map-") + family +
                               ".jsonl.xz is not found ($ROTLIE_DATA, the installed share/rotlie/data, the source tree's data/)");
    const std::string text = runs::read_text_file(*file);
    for (std::size_t at = 0; at < text.size();) {
      const auto end = std::min(text.find('\n', at), text.size());
      const std::string line = text.substr(at, end - at);
      at = end + 1;
      const auto found = wanted.find(key_of_line(line));
      if (found != wanted.end()) lines_[found->second].push_back(line);
    }
  }
}

std::vector<std::string> shipped_map_lines::at(std::pair<int, int> point) const {
  const auto found = lines_.find(point);
  return found == lines_.end() ? std::vector<std::string>{} : found->second;
}

schemes::scheme_table table_from_maps(const lie::moments_of_inertia& body, const std::vector<std::string>& lines) {
  const auto [perm, reference_remainder] = reference_at(body);
  const std::string reference = std::string(solver::map_reference_scheme) + ":" + perm;
  const auto winner = map_winner(lines);
  if (!winner) return *schemes::reference_scheme(reference);
  // SCHEME:PERM:LABEL at the grid body: the same system solved for this body, its best real solution
  // (the label counts solutions at the grid body; the best is what the map chose there)
  const std::string& name = winner->second;
  const auto first = name.find(':'), second = name.find(':', first + 1);
  const auto solved = solver::solve_dedicated(body, {name.substr(0, first)}, {name.substr(first + 1, second - first - 1)}, 40);
  if (solved.solutions.empty()) return *schemes::reference_scheme(reference);
  const auto& best = solved.solutions.front();  // sorted by ‖H_R5‖
  const double gain = reference_remainder / best.analytic_remainder *
                      std::pow(static_cast<double>(solver::reference_cost(solver::map_reference_scheme)) / solver::family_cost(winner->first), 4);
  return gain > 1 ? solver::scheme_table_of(best, body) : *schemes::reference_scheme(reference);
}

}  // namespace rotlie::lammps
