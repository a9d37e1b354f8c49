#pragma once
// `rotlie sweep`: many `binary` runs, one JSON line of options each (the command line's option names
// without the dashes: "system", "primary", "secondary", "density", "mass", "order", "G", "separation",
// "primary-period", "state" (a file's path, or the state itself as an object), "integrator", "h", "T";
// values as text or numbers), one JSON line of results each, in the input's order: the run's `binary`
// JSON with its "index" (0-based input line), or {"index", "status": "refused" | "contact" | "failed",
// "error"} for a run that could not be made (a sweep over impact outcomes meets collisions; it goes on).
// The file is the map's kind (map_file.hpp): a header naming the input (its size and FNV-1a hash),
// lines appended whole, resumable after a kill; the runs are dealt out to the processes in turn (run k
// on process k mod size) and collected by rank 0 as the map's bodies are (map_run.hpp's processes);
// rank 0 alone reads the input and sends its runs to the others.
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
/// object of known options, or that nests deeper than any run's options do (before anything runs).
sweep_plan plan_sweep(const std::filesystem::path& input);

/// {"rotlie_sweep":1,"runs":N,"input":"<hash>"}
std::string sweep_header(const sweep_plan& plan);

/// What a resume finds in `path`: the runs done (the file's lines must be this sweep's, in order).
/// Throws bad_input (--resume: …), leaving the file as it is, for another sweep's file or bytes no kill
/// could leave: a line that is not the next run's result as sweep_line writes it (binary's JSON, or a
/// status of refused, contact or failed with its error) refuses the whole file.
resumed_map resume_sweep_file(const std::filesystem::path& path, const sweep_plan& plan);

/// Run `index` of the plan: its result line.
std::string sweep_line(const sweep_plan& plan, std::size_t index);

struct sweep_output {
  std::filesystem::path path;
  const resumed_map* existing = nullptr;
  std::function<void(const std::string&)> progress;  ///< may be empty
};

/// A completed sweep's runs by outcome (the whole file's, a resume's earlier lines too), and how many
/// of them ran now.
struct sweep_counts {
  std::size_t computed = 0, contact = 0, refused = 0, failed = 0;
  std::size_t now = 0;
  void count(const std::string& result_line);
};

/// Rank 0's part (the whole run on one process).
sweep_counts run_sweep_rank0(const sweep_plan& plan, map_processes& processes, const sweep_output& out);

/// The plan's runs as rank 0 read them, one line each, for the workers (which never read --in: a file
/// replaced meanwhile would mix two inputs' results under one header); and the workers' plan from it.
std::string sweep_inputs_text(const sweep_plan& plan);
sweep_plan sweep_plan_of(const std::string& inputs_text, std::vector<char> done);

/// A worker's part.
void run_sweep_worker(const sweep_plan& plan, map_processes& processes);

}  // namespace rotlie::runs
