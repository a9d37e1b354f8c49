#pragma once
// The processes that share one map. GiNaC and CLN are not thread-safe, so the unit of parallelism
// is a process: MPI ranks when rotlie was started by mpirun (or srun) and built with MPI, else this
// process alone. Only map_distribution_mpi.cpp knows MPI; map_distribution_serial.cpp stands in
// for it in a build without MPI.
#include <memory>
#include <optional>
#include <string>

namespace rotlie::app {

class process_group {
 public:
  /// Joins the MPI job when the environment says rotlie runs under an MPI launcher.
  process_group();
  ~process_group();  ///< leaves it (also while an exception unwinds)
  process_group(const process_group&) = delete;
  process_group& operator=(const process_group&) = delete;

  int rank() const;
  int size() const;

  /// Rank 0's text, delivered to every rank (collective).
  std::string broadcast(const std::string& from_rank0);

  /// A worker's result for body `index`, to rank 0.
  void send_result(int index, const std::string& payload);
  /// A worker's last message: it has no more bodies.
  void send_done();

  struct message {
    int index = -1;  ///< -1: the sender is done
    std::string payload;
  };
  /// Rank 0: the next worker message, waiting for one when `wait`, else nullopt when none is there.
  std::optional<message> receive(bool wait);

  /// Ends every process of the job at once (after a failure on one of them).
  [[noreturn]] void abort(int status);

 private:
  struct state;
  std::unique_ptr<state> state_;
};

/// True when this binary was built with MPI.
bool built_with_mpi();

}  // namespace rotlie::app
