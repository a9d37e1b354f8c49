// rotlie sweep: many `binary` runs from a JSON-lines file, one result line each, resumable, shared
// among MPI ranks when started by mpirun: the map's machinery (its processes, its file writer and
// resume rules) with runs::run_sweep_rank0 and run_sweep_worker doing the work. The lock is the
// results file's own (runs::exclusive_file), and rank 0 alone reads --in, sending its runs to the others.
#include <filesystem>
#include <iostream>
#include <memory>

#include "arguments.hpp"
#include "commands.hpp"
#include "map_distribution.hpp"
#include "progress.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/sweep_run.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

struct prepared_sweep {
  runs::sweep_plan plan;
  runs::resumed_map existing;
  fs::path path;
  std::shared_ptr<runs::exclusive_file> lock;  ///< the results file, held until the sweep is written
};

prepared_sweep prepare(const sweep_options& o) {
  if (o.in.empty()) throw usage_error("--in is required (a JSON-lines file of binary runs)");
  if (o.out.empty()) throw usage_error("--out is required (the results file)");
  prepared_sweep p;
  p.plan = runs::plan_sweep(o.in);
  p.path = o.out;
  const fs::path folder = p.path.has_parent_path() ? p.path.parent_path() : fs::path(".");
  check_output_folder(folder.string(), "--out");
  fs::create_directories(folder);
  check_output_file(p.path.string(), "--out");
  p.lock = std::make_shared<runs::exclusive_file>(p.path, "--out");  // a second sweep into the file, by any name, stops here
  p.existing.done.assign(p.plan.inputs.size(), 0);
  const bool exists = !p.lock->created() && fs::exists(p.path);
  if (exists && !o.resume)
    throw usage_error("--out: " + runs::printable_path(p.path) + " exists: continue it with --resume, or choose another file; it is left as it is");
  if (exists) {
    p.existing = runs::resume_sweep_file(p.path, p.plan);
    p.plan.done = p.existing.done;
  }
  return p;
}

int run_rank0(const sweep_options& o, process_group& group) {
  prepared_sweep p = prepared_on_rank0(group, [&] { return prepare(o); });
  tell_workers_to_start(group, p.plan.done);
  progress_line progress;
  const runs::sweep_output out{.path = p.path, .existing = &p.existing, .progress = [&progress](const std::string& line) { progress.show(line); }};
  if (group.size() > 1) group.broadcast(runs::sweep_inputs_text(p.plan));
  const auto n = runs::run_sweep_rank0(p.plan, group, out);
  std::cout << "sweep of " << p.plan.inputs.size() << " runs: " << n.computed << " computed, " << n.contact << " contact, " << n.refused
            << " refused, " << n.failed << " failed (" << n.now << " run now by " << group.size()
            << (group.size() == 1 ? " process" : " processes") << "), in " << runs::printable_path(p.path) << "\n";
  return n.refused + n.failed > 0 ? exit_runs_not_made : 0;
}

// The runs come from rank 0: a worker never opens --in.
int run_worker(const sweep_options&, process_group& group) {
  return when_rank0_starts(group, [&](std::vector<char> done) {
    const auto plan = runs::sweep_plan_of(group.broadcast(""), std::move(done));
    runs::run_sweep_worker(plan, group);
  });
}

}  // namespace

int run_sweep(const sweep_options& options) { return run_shared(options, run_rank0, run_worker); }

}  // namespace rotlie::app
