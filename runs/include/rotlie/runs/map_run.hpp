#pragma once
// One map run (LV section 5, Figs. 7–10), whoever asks for it: `rotlie map` on one process or on MPI
// ranks, and the report's maps. How the work is shared is pluggable (map_processes): one process
// alone, or the command line's MPI ranks, which only apps/rotlie knows.
//
// Every process computes the rows of the grid dealt out to it in turn and sends each body's line to
// rank 0, which keeps them in the grid's order: the lines of a run on any number of processes, killed
// and resumed or not, are the lines of one uninterrupted process. A screened map's lines are final
// only after the neighbour check, whose exact solves are shared among the processes the same way.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/bch/families.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/solver/body_grid.hpp"

namespace rotlie::runs {

/// The processes that share one map (rank 0 collects; the others are workers).
class map_processes {
 public:
  virtual ~map_processes() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Rank 0's text, delivered to every process (collective).
  virtual std::string broadcast(const std::string& from_rank0) = 0;
  /// A worker's lines (body or task index, line), to rank 0 in one message, without waiting for it.
  virtual void send_results(const std::vector<std::pair<std::size_t, std::string>>& lines) = 0;
  /// A worker's last message of a phase, once every earlier one was delivered.
  virtual void send_done() = 0;

  struct message {
    std::size_t index = 0;
    std::string payload;
  };
  /// Rank 0: the lines that have arrived and how many workers said they were done; when `wait`, it
  /// waits until there is at least one of either.
  struct delivery {
    std::vector<message> lines;
    int done = 0;
  };
  virtual delivery receive(bool wait) = 0;
};

/// This process alone.
class single_process final : public map_processes {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::string broadcast(const std::string& from_rank0) override { return from_rank0; }
  void send_results(const std::vector<std::pair<std::size_t, std::string>>&) override;  ///< throws: nobody to send to
  void send_done() override {}
  delivery receive(bool) override { return {}; }
};

/// What every process knows of the map before it starts.
struct map_plan {
  std::string family;
  int K = 0;
  bch::map_method method = bch::map_method::exact;
  std::vector<solver::grid_body> bodies;  ///< solver::asymmetric_grid(K)
  std::vector<char> done;                 ///< per body: its line is already in the file (a resume)
};

/// The plan of a map of `family` at grid K by `method`, nothing done yet.
map_plan plan_map(const std::string& family, int K, bch::map_method method);

/// What rank 0 does with the lines besides collecting them.
struct map_run_output {
  /// The map file, appended to in the grid's order (a screened map's is rewritten whole by the
  /// neighbour check); empty: no file, the lines come back in map_run_result::lines.
  std::filesystem::path path;
  const resumed_map* existing = nullptr;  ///< the file's lines already there (a resume; its done marks are the plan's), or null
  /// Each final line, in the grid's order, as soon as it is final (may be empty).
  std::function<void(const std::string&)> line;
  /// One line of progress (may be empty).
  std::function<void(const std::string&)> progress;
};

struct map_run_result {
  std::vector<std::string> lines;  ///< every body's line in grid order (without a file)
  std::size_t computed = 0;        ///< bodies computed by this run
  std::optional<neighbour_check_counts> neighbour_check;  ///< a screened map's check, when it ran
  double seconds = 0;              ///< wall time
};

/// Rank 0's part (the whole run on one process). Throws std::runtime_error when a process did not
/// deliver its share, std::invalid_argument when `out.existing` is not the plan's resume.
map_run_result run_map_rank0(const map_plan& plan, map_processes& processes, const map_run_output& out);

/// A worker's part: its rows, then its share of the neighbour check until rank 0 says the end.
void run_map_worker(const map_plan& plan, map_processes& processes);

}  // namespace rotlie::runs
