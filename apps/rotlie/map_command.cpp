// rotlie map: the body-set maps of LV section 5 (Figs. 7–10), one JSON line per body, resumable,
// distributed over MPI ranks when started by mpirun.
//
// Every rank computes the bodies of a fixed schedule (the rows of the grid, s fixed, dealt out in
// turn) and sends each line to rank 0, which writes the lines in the grid's order: the file of a run
// on any number of processes, killed and resumed or not, is the file of one uninterrupted process.
// A line is appended with one write and is whole or absent; a resume drops a torn last line.
// By default (--fast) a row is computed as a whole, by continuation (N: solver/continued_map.hpp;
// P: the screened path, solver/screened_map.hpp), so a resume recomputes a row it finds incomplete
// and writes only its missing lines: the result of a body never depends on where a run stopped or
// on the number of processes. Once every row of a screened map is done, the neighbour check
// (runs/map_neighbour_check.hpp) runs over the whole map, its exact solves shared among the ranks in
// the same way, and the file is rewritten whole with the check's counts in its header.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "map_distribution.hpp"
#include "progress.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* default_folder = "rotlie-map";

// The asymmetric grid is K rows (1 ≤ i ≤ K − 1) of K bodies (0 ≤ j ≤ K − 1): row r holds the
// indices r K … r K + K − 1. Rows are dealt out to the ranks in turn.
int owner_of_row(std::size_t row, int ranks) { return static_cast<int>(row % static_cast<std::size_t>(ranks)); }

// --grid 1 has no asymmetric body (it once wrote an empty map with exit 0); 2 has the flat (1/2, 0).
int checked_grid(const std::string& text) {
  return static_cast<int>(parse_integer_in_range(text, "--grid", 2, solver::max_grid_divisions));
}

// Rank 0's writer: lines arrive in any order and leave in the grid's order.
class ordered_writer {
 public:
  ordered_writer(std::vector<std::size_t> todo, runs::map_file_writer* file, bool echo, std::vector<std::string>* keep)
      : todo_(std::move(todo)), file_(file), echo_(echo), keep_(keep) {}
  void add(std::size_t index, std::string line) {
    pending_.emplace(index, std::move(line));
    while (next_ < todo_.size()) {
      const auto found = pending_.find(todo_[next_]);
      if (found == pending_.end()) break;
      if (file_) file_->append(found->second);
      if (echo_) std::cout << found->second << "\n" << std::flush;
      if (keep_) (*keep_)[found->first] = found->second;
      pending_.erase(found);
      ++next_;
    }
  }
  std::size_t written() const { return next_; }
  bool complete() const { return next_ == todo_.size(); }

 private:
  std::vector<std::size_t> todo_;
  runs::map_file_writer* file_;
  bool echo_;
  std::vector<std::string>* keep_;
  std::map<std::size_t, std::string> pending_;
  std::size_t next_ = 0;
};

std::string duration_text(double seconds) {
  std::ostringstream s;
  s.precision(seconds < 10 ? 2 : 3);
  if (seconds < 120) s << seconds << " s";
  else if (seconds < 7200) s << seconds / 60 << " min";
  else s << seconds / 3600 << " h";
  return s.str();
}

// The neighbour check's tasks shared among the ranks: task n is done by rank n mod size. Rank 0
// hands out each batch (a broadcast); the workers answer as they answer with rows.
class shared_runner {
 public:
  shared_runner(process_group& group, const std::vector<solver::grid_body>& bodies, const std::string& family)
      : group_(group), bodies_(bodies), family_(family) {}
  std::vector<std::string> operator()(const std::vector<runs::neighbour_task>& tasks) {
    if (tasks.empty()) return {};  // an empty batch would read as the end of the work
    if (group_.size() > 1) group_.broadcast(runs::tasks_text(tasks));
    std::vector<std::string> out(tasks.size());
    std::vector<char> have(tasks.size(), 0);
    int workers_left = group_.size() - 1;
    const auto take = [&](bool wait) {
      auto d = group_.receive(wait);
      for (auto& m : d.lines) {
        out.at(m.index) = std::move(m.payload);
        have[m.index] = 1;
      }
      workers_left -= d.done;
    };
    for (std::size_t n = 0; n < tasks.size(); n += static_cast<std::size_t>(group_.size())) {
      out[n] = runs::run_neighbour_task(tasks[n], bodies_, family_);
      have[n] = 1;
      if (group_.size() > 1) take(false);
    }
    while (workers_left > 0) take(true);
    if (std::find(have.begin(), have.end(), 0) != have.end())
      throw std::runtime_error("a process of the MPI job did not deliver all its neighbour-check results");
    return out;
  }
  /// Tells the workers there is no more work.
  void finish() {
    if (group_.size() > 1) group_.broadcast("");
  }

 private:
  process_group& group_;
  const std::vector<solver::grid_body>& bodies_;
  std::string family_;
};

// A worker's part of the neighbour check: batches until rank 0 sends an empty one.
void serve_neighbour_check(process_group& group, const std::vector<solver::grid_body>& bodies, const std::string& family) {
  for (;;) {
    const std::string text = group.broadcast("");
    if (text.empty()) return;
    const auto tasks = runs::tasks_from_text(text);
    std::vector<std::pair<std::size_t, std::string>> results;
    for (std::size_t n = static_cast<std::size_t>(group.rank()); n < tasks.size(); n += static_cast<std::size_t>(group.size()))
      results.emplace_back(n, runs::run_neighbour_task(tasks[n], bodies, family));
    if (!results.empty()) group.send_results(results);
    group.send_done();
  }
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
    << " asymmetric bodies (" << computed << " computed now in " << duration_text(seconds) << " by " << processes
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
  prepared_map p;
  try {
    p = prepare(o);
  } catch (const usage_error&) {
    group.broadcast(std::to_string(exit_usage));
    throw;
  } catch (const runs::bad_input&) {
    group.broadcast(std::to_string(exit_usage));
    throw;
  } catch (...) {
    group.broadcast(std::to_string(exit_failure));
    throw;
  }
  group.broadcast("0" + std::string(p.existing.done.begin(), p.existing.done.end()));

  // A screened map's lines are final only after the neighbour check: --json prints them then.
  const bool screened = p.method == bch::map_method::screened;
  std::optional<runs::map_file_writer> file;
  if (!p.path.empty())
    file.emplace(p.path, p.existing, runs::map_header(p.family, p.K, p.bodies.size(), runs::map_method_name(p.method)).dump());
  if (o.json && !screened)
    for (const auto& line : p.existing.lines) std::cout << line << "\n";
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < p.bodies.size(); ++k)
    if (p.existing.done[k] == 0) todo.push_back(k);
  std::vector<std::string> kept(screened && p.path.empty() ? p.bodies.size() : 0);
  ordered_writer writer(todo, file ? &*file : nullptr, o.json && !screened, kept.empty() ? nullptr : &kept);

  progress_line progress;
  const auto start = std::chrono::steady_clock::now();
  const auto show = [&] {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = writer.written();
    std::ostringstream s;
    s << "map " << p.family << " --grid " << p.K << ": " << done << "/" << todo.size() << " bodies on " << group.size()
      << " process(es)";
    if (done > 0) s << ", about " << duration_text(elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done)) << " left";
    progress.show(s.str());
  };
  const auto drain = [&](bool wait, int& workers_left) {
    auto d = group.receive(wait);
    for (auto& m : d.lines) writer.add(m.index, std::move(m.payload));
    workers_left -= d.done;
  };
  int workers_left = group.size() - 1;
  const std::size_t K = static_cast<std::size_t>(p.K);
  for (std::size_t row = 0; row * K < p.bodies.size(); ++row) {
    if (owner_of_row(row, group.size()) != 0) continue;
    for (auto& [k, line] : runs::map_row_lines(p.bodies, row * K, K, p.existing.done, p.family, p.method)) writer.add(k, std::move(line));
    drain(false, workers_left);
    show();
  }
  while (workers_left > 0) {
    drain(true, workers_left);
    show();
  }
  if (!writer.complete()) throw std::runtime_error("a process of the MPI job did not deliver all its bodies");
  if (file) file->finish();
  shared_runner shared(group, p.bodies, p.family);
  if (screened) {
    int pass = 0;
    const runs::neighbour_runner run = [&](const std::vector<runs::neighbour_task>& tasks) {
      progress.show("map " + p.family + " --grid " + std::to_string(p.K) + ": neighbour check, pass " + std::to_string(++pass) +
                    ", " + std::to_string(tasks.size()) + " exact solves on " + std::to_string(group.size()) + " process(es)");
      return shared(tasks);
    };
    if (file) {
      file.reset();  // closed: the check rewrites the file whole
      runs::check_map_file(p.path, p.K, p.bodies, run);
      if (o.json) {
        const auto text = runs::read_map_file(p.path);
        for (std::size_t n = 1; n < text.lines.size(); ++n) std::cout << text.lines[n] << "\n";  // after the header
      }
    } else {
      runs::check_neighbours(p.bodies, kept, run);
      for (const auto& line : kept) std::cout << line << "\n";
    }
  }
  shared.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.json) std::cout << summary(p, seconds, todo.size(), group.size());
  return 0;
}

int run_worker(const map_options& o, process_group& group) {
  const std::string verdict = group.broadcast("");
  if (verdict.empty() || verdict[0] != '0') return verdict.empty() ? exit_failure : verdict[0] - '0';  // rank 0 says why
  const auto& descriptor = runs::family_to_map(o.family);
  const std::string family(descriptor.name);
  const int K = checked_grid(o.grid);
  const auto method = runs::map_method_asked(descriptor, K, o.exact, o.fast);
  const auto bodies = solver::asymmetric_grid(K);
  const std::vector<char> done(verdict.begin() + 1, verdict.end());
  const std::size_t n = static_cast<std::size_t>(K);
  for (std::size_t row = 0; row * n < bodies.size(); ++row)
    if (owner_of_row(row, group.size()) == group.rank())
      group.send_results(runs::map_row_lines(bodies, row * n, n, done, family, method));
  group.send_done();
  serve_neighbour_check(group, bodies, family);
  return 0;
}

}  // namespace

int run_map(const map_options& options) {
  process_group group;
  if (group.rank() == 0) {
    if (group.size() == 1) return run_rank0(options, group);
    try {
      return run_rank0(options, group);
    } catch (const usage_error&) {
      throw;  // before any work was handed out: the other ranks were told and have ended
    } catch (const runs::bad_input&) {
      throw;  // before any work was handed out: the other ranks were told and have ended
    } catch (const runs::folder_in_use&) {
      throw;  // likewise (prepare's refusal, exit 1)
    } catch (const std::exception& e) {
      // After the work was handed out the other ranks would wait for ever: end the whole job.
      std::cerr << "rotlie: error: " << one_line(e.what()) << "\n";
      group.abort(exit_failure);
    }
  }
  try {
    return run_worker(options, group);
  } catch (const std::exception& e) {
    std::cerr << "rotlie: error: rank " << group.rank() << ": " << one_line(e.what()) << "\n";
    group.abort(exit_failure);
  }
}

}  // namespace rotlie::app
