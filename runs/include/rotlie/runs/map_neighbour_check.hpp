#pragma once
// The neighbour check of a screened map (solver/screened_map.hpp). The screened path works row by
// row, and a minimum that is born and dies again between its checkpoints is in no chain of that
// row: the best it names can then be beaten by a system it never completed there. Such a minimum
// is a region of the triangle, not a point, and the rows beside it see it. So, once every row is
// done, each body's best is held against the best system of each of its eight neighbours: that
// system is solved exactly at the body (one system, about 1/90 of a body's exact solve), and where
// it reaches a smaller ‖H_R5‖ the body's line is replaced by the exact solver's. The bodies around
// a replaced one are checked again, until nothing changes. The result depends only on the rows'
// lines, so it is the same on any number of processes and after any resume.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/solver/body_grid.hpp"

namespace rotlie::runs {

/// One piece of work of the check: the exact solve of one system at one body (its smallest ‖H_R5‖),
/// or, with `scheme` empty, the exact solver's map line of the body.
struct neighbour_task {
  std::size_t body = 0;  ///< index in the asymmetric grid
  std::string scheme, permutation;
};

/// Tasks as text (one per line) and back, to hand them to other processes.
std::string tasks_text(const std::vector<neighbour_task>& tasks);
std::vector<neighbour_task> tasks_from_text(const std::string& text);

/// Does one task: the smallest ‖H_R5‖ of the system at the body, as "%.17g" text ("inf" without a
/// real solution, "failed" when the solver throws), or the body's exact map line.
std::string run_neighbour_task(const neighbour_task& task, const std::vector<solver::grid_body>& bodies, const std::string& family);

struct neighbour_check_counts {
  std::size_t probes = 0;    ///< (body, system) exact solves
  std::size_t replaced = 0;  ///< lines replaced by the exact solver's
  int passes = 0;
  std::size_t failed_probes = 0;        ///< probes whose exact solve threw: they show nothing, the line stays
  std::size_t failed_replacements = 0;  ///< beaten bodies whose whole exact solve failed: the line stays
};

/// Runs the check over the body lines of a complete map (lines[k]: body k of `bodies`, the
/// asymmetric grid), replacing lines in place. `run` does a batch of tasks and returns their results
/// in order (on this process: run_neighbour_task; under MPI: shared among the ranks).
using neighbour_runner = std::function<std::vector<std::string>(const std::vector<neighbour_task>&)>;
neighbour_check_counts check_neighbours(const std::vector<solver::grid_body>& bodies, std::vector<std::string>& lines,
                                        const neighbour_runner& run);

/// The check of a complete map file, which it rewrites whole (atomically) with the counts in its
/// header's "neighbour_check". nullopt, and the file untouched, when the header records them already
/// (recorded_neighbour_check).
/// Throws std::runtime_error when a body line is missing or the file cannot be read or written.
std::optional<neighbour_check_counts> check_map_file(const std::filesystem::path& path, int K,
                                                     const std::vector<solver::grid_body>& bodies, const neighbour_runner& run);

/// The counts as a map header records them ("neighbour_check": {"probes", "replaced", "passes"}), and
/// back from a header (nullopt when it has none).
nlohmann::ordered_json neighbour_check_record(const neighbour_check_counts& c);
std::optional<neighbour_check_counts> recorded_neighbour_check(const nlohmann::json& header);

/// "neighbour check: 7,096 systems solved at neighbours' bests, 3 lines replaced by the exact solver's (2 passes)"
std::string neighbour_check_text(const neighbour_check_counts& c);

/// A runner that does every task here, in order.
neighbour_runner local_neighbour_runner(const std::vector<solver::grid_body>& bodies, const std::string& family);

}  // namespace rotlie::runs
