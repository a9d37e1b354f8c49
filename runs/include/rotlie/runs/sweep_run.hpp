#pragma once
// `rotlie sweep`: many `binary` runs, one JSON line of options each (the command line's option names
// without the dashes: "system", "primary", "secondary", "density", "mass", "order", "G", "separation",
// "primary-period", "state" (a file's path, or the state itself as an object), "integrator", "h", "T";
// values as text or numbers), one JSON line of results each, in the input's order: the run's `binary`
// JSON with its "index" (0-based input line), or {"index", "status": "refused" | "contact" | "failed",
// "error"} for a run that could not be made (a sweep over impact outcomes meets collisions; it goes on).
// The file is the map's kind (map_file.hpp): a header naming the input (its size and FNV-1a hash),
// lines appended whole, resumable after a kill; the runs are dealt out to the processes in turn (run k
// on process k mod size) and collected by rank 0 as the map's bodies are (map_run.hpp's processes).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_run.hpp"

namespace rotlie::runs {

struct sweep_plan {
  std::vector<std::string> inputs;  ///< one JSON object per run
  std::string input_hash;           ///< FNV-1a 64 of the input file, hex
  std::vector<char> done;           ///< per run: its line is already in the file (a resume)
};

/// The input file's runs; throws bad_input naming --in and the line for a line that is not a JSON
/// object of known options (before anything runs).
sweep_plan plan_sweep(const std::filesystem::path& input);

/// {"rotlie_sweep":1,"runs":N,"input":"<hash>"}
std::string sweep_header(const sweep_plan& plan);

/// What a resume finds in `path`: the runs done (the file's lines must be this sweep's, in order).
/// Throws bad_input (--resume: …), leaving the file as it is, for another sweep's file or bytes no kill
/// could leave.
resumed_map resume_sweep_file(const std::filesystem::path& path, const sweep_plan& plan);

/// Run `index` of the plan: its result line.
std::string sweep_line(const sweep_plan& plan, std::size_t index);

struct sweep_output {
  std::filesystem::path path;
  const resumed_map* existing = nullptr;
  std::function<void(const std::string&)> progress;  ///< may be empty
};

/// Rank 0's part (the whole run on one process); returns the runs computed now.
std::size_t run_sweep_rank0(const sweep_plan& plan, map_processes& processes, const sweep_output& out);

/// A worker's part.
void run_sweep_worker(const sweep_plan& plan, map_processes& processes);

}  // namespace rotlie::runs
