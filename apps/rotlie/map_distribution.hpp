#pragma once
// The processes that share one map (runs::map_processes). GiNaC and CLN are not thread-safe, so the
// unit of parallelism is a process: MPI ranks when rotlie was started by mpirun (or srun) and built
// with MPI, else this process alone. Only map_distribution_mpi.cpp knows MPI; map_distribution_serial.cpp stands in
// for it in a build without MPI.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <iostream>

#include "arguments.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/map_run.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::app {

class process_group final : public runs::map_processes {
 public:
  /// Joins the MPI job when the environment says rotlie runs under an MPI launcher.
  process_group();
  ~process_group() override;  ///< leaves it (also while an exception unwinds)
  process_group(const process_group&) = delete;
  process_group& operator=(const process_group&) = delete;

  int rank() const override;
  int size() const override;
  std::string broadcast(const std::string& from_rank0) override;
  /// Does not wait for rank 0 (which receives only between its own rows): a blocking send of a large
  /// message left the worker waiting, and spinning, while rank 0 computed, so that one line crossed per
  /// row of rank 0's.
  void send_results(const std::vector<std::pair<std::size_t, std::string>>& lines) override;
  void send_done() override;
  delivery receive(bool wait) override;

  /// Ends every process of the job at once (after a failure on one of them).
  [[noreturn]] void abort(int status);

 private:
  struct state;
  std::unique_ptr<state> state_;
};

/// True when this binary was built with MPI.
bool built_with_mpi();

/// Rank 0's preparation of a shared run: what `prepare()` returns, or, when it throws, the workers told
/// to end with the matching exit status (2 for a refused input, 1 otherwise) and the exception passed on.
template <class Prepare>
auto prepared_on_rank0(process_group& group, Prepare&& prepare) -> decltype(prepare()) {
  try {
    return prepare();
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
}

/// Rank 0's word that the run goes ahead, with the rows already done (one mark per row).
inline void tell_workers_to_start(process_group& group, const std::vector<char>& done) {
  group.broadcast("0" + std::string(done.begin(), done.end()));
}

/// A worker's part once rank 0 says the run goes ahead: `work(done)`, the rows already done; or, when
/// rank 0 refused, the exit status it gave (1 when it said nothing).
template <class Work>
int when_rank0_starts(process_group& group, Work&& work) {
  const std::string verdict = group.broadcast("");
  if (verdict.empty() || verdict[0] != '0') return verdict.empty() ? exit_failure : verdict[0] - '0';
  work(std::vector<char>(verdict.begin() + 1, verdict.end()));
  return 0;
}

/// A run shared among the job's processes (map, sweep), which it joins: `rank0` on rank 0, `worker` on
/// the others. A refusal on rank 0 before any work is handed out (bad arguments, a folder in use:
/// `rank0` tells the workers, which end) is thrown as it is; any later failure ends the whole job at
/// once, since the other ranks would wait for ever.
template <class Options>
int run_shared(const Options& options, int (*rank0)(const Options&, process_group&), int (*worker)(const Options&, process_group&)) {
  process_group group;
  if (group.rank() == 0) {
    if (group.size() == 1) return rank0(options, group);
    try {
      return rank0(options, group);
    } catch (const usage_error&) {
      throw;
    } catch (const runs::bad_input&) {
      throw;
    } catch (const runs::folder_in_use&) {
      throw;
    } catch (const std::exception& e) {
      std::cerr << "rotlie: error: " << runs::one_line(e.what()) << "\n";
      group.abort(exit_failure);
    }
  }
  try {
    return worker(options, group);
  } catch (const std::exception& e) {
    std::cerr << "rotlie: error: rank " << group.rank() << ": " << runs::one_line(e.what()) << "\n";
    group.abort(exit_failure);
  }
}

}  // namespace rotlie::app
