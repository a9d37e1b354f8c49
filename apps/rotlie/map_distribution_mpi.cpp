// process_group over MPI: the only translation unit that includes mpi.h.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "map_distribution.hpp"

namespace rotlie::app {
namespace {

constexpr int result_tag = 1, done_tag = 2;

// Set by Open MPI's mpirun, MPICH's Hydra and Slurm's srun: without one of them rotlie runs alone and
// never starts MPI (a singleton MPI_Init can be slow or fail in containers).
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI failed in ") + what);
}

}  // namespace

struct process_group::state {
  bool joined = false;
  int rank = 0, size = 1;
};

process_group::process_group() : state_(std::make_unique<state>()) {
  if (!launched_by_mpi()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized == 0) check(MPI_Init(nullptr, nullptr), "MPI_Init");
  state_->joined = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &state_->rank);
  MPI_Comm_size(MPI_COMM_WORLD, &state_->size);
}

process_group::~process_group() {
  if (!state_->joined) return;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized == 0) MPI_Finalize();
}

int process_group::rank() const { return state_->rank; }
int process_group::size() const { return state_->size; }

std::string process_group::broadcast(const std::string& from_rank0) {
  if (state_->size == 1) return from_rank0;
  unsigned long long length = from_rank0.size();
  check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD), "MPI_Bcast");
  std::string out = state_->rank == 0 ? from_rank0 : std::string(length, '\0');
  // In pieces below INT_MAX bytes (MPI counts are int).
  constexpr std::size_t piece = 1u << 30;
  for (std::size_t at = 0; at < out.size(); at += piece)
    check(MPI_Bcast(out.data() + at, static_cast<int>(std::min(piece, out.size() - at)), MPI_CHAR, 0, MPI_COMM_WORLD),
          "MPI_Bcast");
  return out;
}

void process_group::send_result(int index, const std::string& payload) {
  // The body index first, then the line: one message, so that results never interleave.
  std::string bytes(sizeof(int), '\0');
  std::memcpy(bytes.data(), &index, sizeof(int));
  bytes += payload;
  check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, 0, result_tag, MPI_COMM_WORLD), "MPI_Send");
}

void process_group::send_done() {
  if (state_->size == 1) return;
  check(MPI_Send(nullptr, 0, MPI_CHAR, 0, done_tag, MPI_COMM_WORLD), "MPI_Send");
}

std::optional<process_group::message> process_group::receive(bool wait) {
  if (state_->size == 1) return std::nullopt;
  MPI_Status status;
  if (wait) {
    check(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
  } else {
    int flag = 0;
    check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
    if (flag == 0) return std::nullopt;
  }
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::vector<char> bytes(static_cast<std::size_t>(count));
  check(MPI_Recv(bytes.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
  message m;
  if (status.MPI_TAG == done_tag) return m;
  if (count < static_cast<int>(sizeof(int))) throw std::runtime_error("a malformed result message");
  std::memcpy(&m.index, bytes.data(), sizeof(int));
  m.payload.assign(bytes.data() + sizeof(int), bytes.size() - sizeof(int));
  return m;
}

void process_group::abort(int status) {
  if (state_->joined) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

bool built_with_mpi() { return true; }

}  // namespace rotlie::app
