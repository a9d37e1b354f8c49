// rotlie map: the body-set maps of LV section 5 (Figs. 7–10), one JSON line per body, resumable,
// distributed over MPI ranks when started by mpirun. The run itself is runs::run_map_rank0 and
// run_map_worker (runs/map_run.hpp); this file checks the options, holds the folder, resumes the file
// and prints the summary. A line is appended with one write and is whole or absent; a resume drops a
// torn last line. By default (--fast) a row is computed as a whole, by continuation (N:
// solver/continued_map.hpp; P: the screened path, solver/screened_map.hpp), so a resume recomputes a
// row it finds incomplete and writes only its missing lines: the result of a body never depends on
// where a run stopped or on the number of processes.
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "map_distribution.hpp"
#include "progress.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_run.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* default_folder = "rotlie-map";

// --grid 1 has no asymmetric body (it once wrote an empty map with exit 0); 2 has the flat (1/2, 0).
int checked_grid(const std::string& text) {
  return static_cast<int>(parse_integer_in_range(text, "--grid", 2, solver::max_grid_divisions));
}

struct prepared_map {
  std::string family;
  bch::map_method method = bch::map_method::exact;
  int K = 0;
  std::vector<solver::grid_body> bodies;
  runs::resumed_map existing;
  fs::path path;  ///< empty: no file (--json alone)
  std::shared_ptr<runs::exclusive_use> lock;  ///< the folder, held until the map is written
};

prepared_map prepare(const map_options& o) {
  prepared_map p;
  const auto& family = runs::family_to_map(o.family);
  p.family = family.name;
  p.K = checked_grid(o.grid);
  p.method = runs::map_method_asked(family, p.K, o.exact, o.fast);  // refuses --fast for R before anything is written
  std::string folder = o.out;
  if (folder.empty() && !o.json) folder = default_folder;
  if (o.resume && folder.empty()) throw usage_error("--resume needs --out (the folder of the map to continue)");
  p.bodies = solver::asymmetric_grid(p.K);
  p.existing.done.assign(p.bodies.size(), 0);
  if (folder.empty()) return p;
  check_output_folder(folder, "--out");
  fs::create_directories(folder);
  p.lock = std::make_shared<runs::exclusive_use>(folder, "--out");  // a second map into the folder stops here
  p.path = runs::map_file_path(folder, p.family);
  check_output_file(p.path.string(), "--out");
  const bool exists = fs::exists(p.path);
  if (exists && !o.resume)
    throw usage_error("--out: " + runs::printable_path(p.path) +
                      " exists: continue it with --resume, or choose another folder; it is left as it is");
  if (exists) p.existing = runs::resume_map_file(p.path, p.family, p.K, runs::map_method_name(p.method), p.bodies);
  return p;
}

std::string summary(const prepared_map& p, double seconds, std::size_t computed, int processes) {
  std::size_t bodies = 0, failed = 0, better = 0, with_ratio = 0, singular = 0;
  const auto text = runs::read_map_file(p.path);
  for (std::size_t n = 1; n < text.lines.size(); ++n) {  // after the header
    const auto j = nlohmann::json::parse(text.lines[n], nullptr, false);
    if (j.is_discarded()) continue;
    ++bodies;
    if (j.contains("failed")) ++failed;
    if (j.contains("ratio") && j["ratio"].is_number()) {
      ++with_ratio;
      if (j["ratio"].get<double>() > 1) ++better;
    }
    if (j.contains("singular") && !j["singular"].empty()) ++singular;
  }
  std::ostringstream s;
  s << "map of family " << p.family << " at --grid " << p.K << ": " << bodies << " of " << p.bodies.size()
    << " asymmetric bodies (" << computed << " computed now in " << runs::duration_text(seconds) << " by " << processes
    << (processes == 1 ? " process" : " processes") << ") in "
    << p.path.string() << "\n";
  if (with_ratio > 0)
    s << p.family << " better than " << solver::map_reference_scheme << " at equal cost (ratio > 1) at " << better << " of "
      << with_ratio << " bodies (" << 100.0 * static_cast<double>(better) / static_cast<double>(with_ratio) << " %)\n";
  s << "bodies with a singular system: " << singular << "; bodies whose solve failed: " << failed << "\n";
  const auto header = text.lines.empty() ? nlohmann::json() : nlohmann::json::parse(text.lines.front(), nullptr, false);
  if (const auto checked = runs::recorded_neighbour_check(header)) s << runs::neighbour_check_text(*checked) << "\n";
  return s.str();
}

int run_rank0(const map_options& o, process_group& group) {
  prepared_map p = prepared_on_rank0(group, [&] { return prepare(o); });
  tell_workers_to_start(group, p.existing.done);
  const runs::map_plan plan{p.family, p.K, p.method, p.bodies, p.existing.done};
  progress_line progress;
  runs::map_run_output out{.path = p.path,
                           .existing = p.path.empty() ? nullptr : &p.existing,  // --json alone: no file, nothing resumed
                           .line = nullptr,
                           .progress = [&progress](const std::string& line) { progress.show(line); }};
  if (o.json) out.line = [](const std::string& line) { std::cout << line << "\n" << std::flush; };
  const auto r = runs::run_map_rank0(plan, group, out);
  if (!o.json) std::cout << summary(p, r.seconds, r.computed, group.size());
  return 0;
}

int run_worker(const map_options& o, process_group& group) {
  return when_rank0_starts(group, [&](std::vector<char> done) {
    const auto& descriptor = runs::family_to_map(o.family);
    const int K = checked_grid(o.grid);
    auto plan = runs::plan_map(std::string(descriptor.name), K, runs::map_method_asked(descriptor, K, o.exact, o.fast));
    plan.done = std::move(done);
    runs::run_map_worker(plan, group);
  });
}

}  // namespace

int run_map(const map_options& options) { return run_shared(options, run_rank0, run_worker); }

}  // namespace rotlie::app
