#include "rotlie/runs/map_neighbour_check.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {
namespace {

// What the check needs of a line: its best system (SCHEME:PERM, empty when none) and its ‖H_R5‖.
struct line_best {
  std::string system;
  double remainder = std::numeric_limits<double>::infinity();
  bool failed = false;
};

line_best best_of(const std::string& line) {
  line_best b;
  const auto j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.contains("failed")) {
    b.failed = true;
    return b;
  }
  if (j.contains("best") && j["best"].is_string()) {
    const std::string label = j["best"].get<std::string>();  // SCHEME:PERM:LABEL
    const auto last = label.rfind(':');
    // SCHEME:PERM, or nothing for a label of another shape (not a system to hand to the solver)
    if (last != std::string::npos && last > 0 && label.find(':') < last) b.system = label.substr(0, last);
  }
  if (j.contains("remainder") && j["remainder"].is_number()) b.remainder = j["remainder"].get<double>();
  return b;
}

// Each body's index in `bodies` by its grid indices (i, j).
std::map<std::pair<int, int>, std::size_t> index_by_place(const std::vector<solver::grid_body>& bodies) {
  std::map<std::pair<int, int>, std::size_t> at;
  for (std::size_t k = 0; k < bodies.size(); ++k) at[{bodies[k].i, bodies[k].j}] = k;
  return at;
}

// A smaller ‖H_R5‖ than the line's, beyond the digits both were computed to.
bool beats(double probe, double line) { return probe < line * (1 - 1e-9); }

// A probe whose exact solve threw.
constexpr const char* failed_probe = "failed";

}  // namespace

std::string tasks_text(const std::vector<neighbour_task>& tasks) {
  std::string out;
  for (const auto& t : tasks) out += std::to_string(t.body) + " " + (t.scheme.empty() ? "-" : t.scheme + " " + t.permutation) + "\n";
  return out;
}

std::vector<neighbour_task> tasks_from_text(const std::string& text) {
  std::vector<neighbour_task> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    neighbour_task t;
    std::string scheme;
    if (!(words >> t.body >> scheme)) throw std::runtime_error("a neighbour-check task that does not parse: " + line);
    if (scheme != "-") {
      t.scheme = scheme;
      if (!(words >> t.permutation)) throw std::runtime_error("a neighbour-check task without a permutation: " + line);
    }
    out.push_back(std::move(t));
  }
  return out;
}

std::string run_neighbour_task(const neighbour_task& task, const std::vector<solver::grid_body>& bodies, const std::string& family) {
  lie::stop_point();
  const auto& g = bodies.at(task.body);
  if (task.scheme.empty()) return exact_map_line(g, family);
  double smallest = std::numeric_limits<double>::infinity();
  try {
    const auto r = solver::solve_dedicated(g.body, {task.scheme}, {task.permutation}, solver::map_digits);
    for (const auto& s : r.solutions) smallest = std::min(smallest, s.analytic_remainder);
  } catch (const std::exception&) {
    return failed_probe;  // the system cannot be solved at this body: it shows nothing there
  }
  if (!std::isfinite(smallest)) return "inf";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", smallest);
  return text;
}

neighbour_runner local_neighbour_runner(const std::vector<solver::grid_body>& bodies, const std::string& family) {
  return [&bodies, family](const std::vector<neighbour_task>& tasks) {
    std::vector<std::string> out;
    for (const auto& t : tasks) out.push_back(run_neighbour_task(t, bodies, family));
    return out;
  };
}

neighbour_check_counts check_neighbours(const std::vector<solver::grid_body>& bodies, std::vector<std::string>& lines,
                                        const neighbour_runner& run) {
  if (lines.size() != bodies.size()) throw std::invalid_argument("check_neighbours needs one line per body");
  const auto at = index_by_place(bodies);
  std::vector<line_best> best(lines.size());
  for (std::size_t k = 0; k < lines.size(); ++k) best[k] = best_of(lines[k]);
  const auto neighbours = [&](std::size_t k) {
    std::vector<std::size_t> out;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        if (di == 0 && dj == 0) continue;
        const auto found = at.find({bodies[k].i + di, bodies[k].j + dj});
        if (found != at.end()) out.push_back(found->second);
      }
    return out;
  };

  neighbour_check_counts counts;
  std::set<std::pair<std::size_t, std::string>> probed;  // (body, system) solved already
  std::set<std::size_t> around;                          // bodies to look at in this pass
  for (std::size_t k = 0; k < lines.size(); ++k) around.insert(k);
  while (!around.empty()) {
    std::vector<neighbour_task> probes;
    for (const std::size_t k : around) {
      if (best[k].failed) continue;  // the exact solver failed there: nothing to compare with
      for (const std::size_t n : neighbours(k)) {
        const std::string& system = best[n].system;
        if (best[n].failed || system.empty() || system == best[k].system || !probed.insert({k, system}).second) continue;
        const auto colon = system.find(':');
        probes.push_back({k, system.substr(0, colon), system.substr(colon + 1)});
      }
    }
    if (probes.empty()) break;
    ++counts.passes;
    counts.probes += probes.size();
    const auto results = run(probes);
    std::set<std::size_t> beaten;
    for (std::size_t p = 0; p < probes.size(); ++p) {
      if (results.at(p) == failed_probe) {
        ++counts.failed_probes;
        continue;
      }
      if (beats(std::stod(results.at(p)), best[probes[p].body].remainder)) beaten.insert(probes[p].body);
    }
    around.clear();
    if (beaten.empty()) break;
    std::vector<neighbour_task> replace;
    for (const std::size_t k : beaten) replace.push_back({k, "", ""});
    const auto exact = run(replace);
    for (std::size_t r = 0; r < replace.size(); ++r) {
      const std::size_t k = replace[r].body;
      const auto exact_best = best_of(exact.at(r));
      if (exact_best.failed) {  // the whole body's exact solve failed where one system's did not: keep the line
        ++counts.failed_replacements;
        continue;
      }
      lines[k] = exact.at(r);
      best[k] = exact_best;
      ++counts.replaced;
      around.insert(k);
      for (const std::size_t n : neighbours(k)) around.insert(n);
    }
  }
  return counts;
}

std::optional<neighbour_check_counts> check_map_file(const std::filesystem::path& path, int K,
                                                     const std::vector<solver::grid_body>& bodies, const neighbour_runner& run) {
  const auto text = read_map_file(path);
  if (text.lines.empty()) throw std::runtime_error(printable_path(path) + " is empty");
  auto header = nlohmann::ordered_json::parse(text.lines.front(), nullptr, false);
  if (header.is_discarded() || !header.is_object()) throw std::runtime_error(printable_path(path) + " has no map header");
  if (recorded_neighbour_check(header)) return std::nullopt;
  const auto at = index_by_place(bodies);
  std::vector<std::string> lines(bodies.size());
  for (std::size_t n = 1; n < text.lines.size(); ++n) {
    const auto ij = map_line_indices(nlohmann::json::parse(text.lines[n], nullptr, false), K);
    const auto found = ij ? at.find(*ij) : at.end();
    if (found == at.end()) throw std::runtime_error(printable_path(path) + ": line " + std::to_string(n + 1) + " is not a body of the map");
    lines[found->second] = text.lines[n];
  }
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (lines[k].empty()) throw std::runtime_error(printable_path(path) + " lacks body " + std::to_string(k + 1) + ": the check needs a complete map");
  const auto counts = check_neighbours(bodies, lines, run);
  header["neighbour_check"] = neighbour_check_record(counts);
  std::string out = header.dump() + "\n";
  for (const auto& l : lines) out += l + "\n";
  write_file_atomically(path, out);
  return counts;
}

nlohmann::ordered_json neighbour_check_record(const neighbour_check_counts& c) {
  return {{"probes", c.probes}, {"replaced", c.replaced}, {"passes", c.passes}, {"failed_probes", c.failed_probes},
          {"failed_replacements", c.failed_replacements}};
}

std::optional<neighbour_check_counts> recorded_neighbour_check(const nlohmann::json& header) {
  if (!header.is_object() || !header.contains("neighbour_check") || !header["neighbour_check"].is_object()) return std::nullopt;
  const auto& r = header["neighbour_check"];
  const auto count = [&](const char* name) { return r.contains(name) && r[name].is_number_unsigned() ? r[name].get<std::size_t>() : 0; };
  neighbour_check_counts c;
  c.probes = count("probes");
  c.replaced = count("replaced");
  c.passes = static_cast<int>(count("passes"));
  c.failed_probes = count("failed_probes");
  c.failed_replacements = count("failed_replacements");
  return c;
}

std::string neighbour_check_text(const neighbour_check_counts& c) {
  return "neighbour check: " + std::to_string(c.probes) + " systems solved exactly at their neighbours' bodies, " +
         std::to_string(c.replaced) + (c.replaced == 1 ? " line" : " lines") + " replaced by the exact solver's (" +
         std::to_string(c.passes) + (c.passes == 1 ? " pass)" : " passes)") +
         (c.failed_probes + c.failed_replacements > 0
              ? "; " + std::to_string(c.failed_probes) + " systems and " + std::to_string(c.failed_replacements) +
                    " bodies the exact solver could not solve, their lines kept"
              : std::string());
}

}  // namespace rotlie::runs
