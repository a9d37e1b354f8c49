#include "rotlie/runs/map_run.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <stdexcept>

#include "ordered_lines.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::runs {
namespace {

// Rows (K bodies each) are dealt out to the processes in turn.
int owner_of_row(std::size_t row, int processes) { return static_cast<int>(row % static_cast<std::size_t>(processes)); }

// The neighbour check's tasks shared among the processes: task n is done by process n mod size. Rank
// 0 hands out each batch (a broadcast); the workers answer as they answer with rows.
class shared_runner {
 public:
  shared_runner(map_processes& processes, const map_plan& plan) : processes_(processes), plan_(plan) {}
  std::vector<std::string> operator()(const std::vector<neighbour_task>& tasks) {
    if (tasks.empty()) return {};  // an empty batch would read as the end of the work
    const auto size = static_cast<std::size_t>(processes_.size());
    if (size > 1) processes_.broadcast(tasks_text(tasks));
    std::vector<std::string> out(tasks.size());
    std::vector<char> have(tasks.size(), 0);
    int workers_left = processes_.size() - 1;
    const auto take = [&](bool wait) {
      auto d = processes_.receive(wait);
      for (auto& m : d.lines) {
        out.at(m.index) = std::move(m.payload);
        have[m.index] = 1;
      }
      workers_left -= d.done;
    };
    for (std::size_t n = 0; n < tasks.size(); n += size) {
      out[n] = run_neighbour_task(tasks[n], plan_.bodies, plan_.family);
      have[n] = 1;
      if (size > 1) take(false);
    }
    while (workers_left > 0) take(true);
    if (std::find(have.begin(), have.end(), 0) != have.end())
      throw std::runtime_error("a process of the MPI job did not deliver all its neighbour-check results");
    return out;
  }
  /// Tells the workers there is no more work.
  void finish() {
    if (processes_.size() > 1) processes_.broadcast("");
  }

 private:
  map_processes& processes_;
  const map_plan& plan_;
};

}  // namespace

void single_process::send_results(const std::vector<std::pair<std::size_t, std::string>>&) {
  throw std::logic_error("no other process to send to");
}

map_plan plan_map(const std::string& family, int K, bch::map_method method) {
  map_plan p{family, K, method, solver::asymmetric_grid(K), {}};
  p.done.assign(p.bodies.size(), 0);
  return p;
}

map_run_result run_map_rank0(const map_plan& plan, map_processes& processes, const map_run_output& out) {
  if (plan.done.size() != plan.bodies.size()) throw std::invalid_argument("run_map_rank0: the plan needs one done mark per body");
  if (out.existing && (out.path.empty() || out.existing->done != plan.done))
    throw std::invalid_argument("run_map_rank0: a resumed file's lines need its path and the plan's done marks");
  map_run_result result;
  const auto start = std::chrono::steady_clock::now();
  const bool screened = plan.method == bch::map_method::screened;
  static const resumed_map nothing_yet;
  std::optional<map_file_writer> file;
  if (!out.path.empty())
    file.emplace(out.path, out.existing ? *out.existing : nothing_yet,
                 map_header(plan.family, plan.K, plan.bodies.size(), map_method_name(plan.method)).dump());
  // A screened map's lines are final only after the neighbour check: they are handed on then.
  if (out.line && !screened && out.existing)
    for (const auto& line : out.existing->lines) out.line(line);
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < plan.bodies.size(); ++k)
    if (plan.done[k] == 0) todo.push_back(k);
  if (!file) result.lines.resize(plan.bodies.size());
  ordered_lines collected(todo, file ? &*file : nullptr, out.line && !screened ? &out.line : nullptr,
                          file ? nullptr : &result.lines);

  const std::string what = "map " + plan.family + " --grid " + std::to_string(plan.K);
  const auto show = [&] {
    if (!out.progress) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = collected.written();
    std::ostringstream s;
    s << what << ": " << done << "/" << todo.size() << " bodies on " << processes.size() << " process(es)";
    if (done > 0) s << ", about " << duration_text(elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done)) << " left";
    out.progress(s.str());
  };
  const auto drain = [&](bool wait, int& workers_left) {
    auto d = processes.receive(wait);
    for (auto& m : d.lines) collected.add(m.index, std::move(m.payload));
    workers_left -= d.done;
  };
  int workers_left = processes.size() - 1;
  const auto K = static_cast<std::size_t>(plan.K);
  for (std::size_t row = 0; row * K < plan.bodies.size(); ++row) {
    if (owner_of_row(row, processes.size()) != 0) continue;
    for (auto& [k, line] : map_row_lines(plan.bodies, row * K, K, plan.done, plan.family, plan.method)) collected.add(k, std::move(line));
    drain(false, workers_left);
    show();
  }
  while (workers_left > 0) {
    drain(true, workers_left);
    show();
  }
  if (!collected.complete()) throw std::runtime_error("a process of the MPI job did not deliver all its bodies");
  if (file) file->finish();
  result.computed = todo.size();

  shared_runner shared(processes, plan);
  if (screened) {
    int pass = 0;
    const neighbour_runner run = [&](const std::vector<neighbour_task>& tasks) {
      if (out.progress)
        out.progress(what + ": neighbour check, pass " + std::to_string(++pass) + ", " + std::to_string(tasks.size()) +
                     " exact solves on " + std::to_string(processes.size()) + " process(es)");
      return shared(tasks);
    };
    if (file) {
      file.reset();  // closed: the check rewrites the file whole
      result.neighbour_check = check_map_file(out.path, plan.K, plan.bodies, run);
      if (out.line) {
        const auto text = read_map_file(out.path);
        for (std::size_t n = 1; n < text.lines.size(); ++n) out.line(text.lines[n]);  // after the header
      }
    } else {
      result.neighbour_check = check_neighbours(plan.bodies, result.lines, run);
      if (out.line)
        for (const auto& line : result.lines) out.line(line);
    }
  }
  shared.finish();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void run_map_worker(const map_plan& plan, map_processes& processes) {
  const auto K = static_cast<std::size_t>(plan.K);
  for (std::size_t row = 0; row * K < plan.bodies.size(); ++row)
    if (owner_of_row(row, processes.size()) == processes.rank())
      processes.send_results(map_row_lines(plan.bodies, row * K, K, plan.done, plan.family, plan.method));
  processes.send_done();
  // the neighbour check: batches until rank 0 sends an empty one
  for (;;) {
    const std::string text = processes.broadcast("");
    if (text.empty()) return;
    const auto tasks = tasks_from_text(text);
    std::vector<std::pair<std::size_t, std::string>> results;
    for (auto n = static_cast<std::size_t>(processes.rank()); n < tasks.size(); n += static_cast<std::size_t>(processes.size()))
      results.emplace_back(n, run_neighbour_task(tasks[n], plan.bodies, plan.family));
    if (!results.empty()) processes.send_results(results);
    processes.send_done();
  }
}

}  // namespace rotlie::runs
