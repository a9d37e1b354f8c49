// process_group over MPI: the only translation unit that includes mpi.h.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <limits>
#include <list>
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

// A row's lines in one message: for each line its body index and length (8 bytes each), then its bytes.
std::vector<char> pack(const std::vector<std::pair<std::size_t, std::string>>& lines) {
  std::vector<char> bytes;
  for (const auto& [index, line] : lines) {
    const std::uint64_t head[2] = {index, line.size()};
    const char* h = reinterpret_cast<const char*>(head);
    bytes.insert(bytes.end(), h, h + sizeof head);
    bytes.insert(bytes.end(), line.begin(), line.end());
  }
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("a row's results exceed one MPI message");
  return bytes;
}

void unpack(const std::vector<char>& bytes, std::vector<process_group::message>& out) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    std::uint64_t head[2];
    if (bytes.size() - at < sizeof head) throw std::runtime_error("a malformed result message");
    std::memcpy(head, bytes.data() + at, sizeof head);
    at += sizeof head;
    if (bytes.size() - at < head[1]) throw std::runtime_error("a malformed result message");
    out.push_back({static_cast<std::size_t>(head[0]), std::string(bytes.data() + at, head[1])});
    at += head[1];
  }
}

struct in_flight {
  std::vector<char> bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

// Removes the transfers that have completed, after handing each to `done`.
template <class Done>
void drop_completed(std::list<in_flight>& transfers, Done done) {
  for (auto it = transfers.begin(); it != transfers.end();) {
    int complete = 0;
    check(MPI_Test(&it->request, &complete, MPI_STATUS_IGNORE), "MPI_Test");
    if (complete) done(*it);
    it = complete ? transfers.erase(it) : std::next(it);
  }
}

}  // namespace

struct process_group::state {
  bool joined = false;
  int rank = 0, size = 1;
  std::list<in_flight> sends;     // a worker's rows not yet taken by rank 0
  std::list<in_flight> receives;  // rank 0's receives started, not yet complete
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

void process_group::send_results(const std::vector<std::pair<std::size_t, std::string>>& lines) {
  auto& sends = state_->sends;
  sends.push_back({pack(lines), MPI_REQUEST_NULL});
  check(MPI_Isend(sends.back().bytes.data(), static_cast<int>(sends.back().bytes.size()), MPI_CHAR, 0, result_tag,
                  MPI_COMM_WORLD, &sends.back().request),
        "MPI_Isend");
  drop_completed(sends, [](const in_flight&) {});  // the rows rank 0 has taken
}

void process_group::send_done() {
  if (state_->size == 1) return;
  for (auto& s : state_->sends) check(MPI_Wait(&s.request, MPI_STATUS_IGNORE), "MPI_Wait");
  state_->sends.clear();
  check(MPI_Send(nullptr, 0, MPI_CHAR, 0, done_tag, MPI_COMM_WORLD), "MPI_Send");
}

process_group::delivery process_group::receive(bool wait) {
  delivery d;
  if (state_->size == 1) return d;
  auto& receives = state_->receives;
  const auto deliver = [&](const in_flight& r) { unpack(r.bytes, d.lines); };
  for (;;) {
    // start a receive for every message that has arrived (matched in the order each worker sent them)
    for (;;) {
      int flag = 0;
      MPI_Message m;
      MPI_Status status;
      check(MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &m, &status), "MPI_Improbe");
      if (flag == 0) break;
      if (status.MPI_TAG == done_tag) {
        check(MPI_Mrecv(nullptr, 0, MPI_CHAR, &m, MPI_STATUS_IGNORE), "MPI_Mrecv");
        // the worker's rows were all taken before it said so: their receives complete without it
        for (auto& r : receives) {
          check(MPI_Wait(&r.request, MPI_STATUS_IGNORE), "MPI_Wait");
          deliver(r);
        }
        receives.clear();
        ++d.done;
        continue;
      }
      int count = 0;
      MPI_Get_count(&status, MPI_CHAR, &count);
      receives.push_back({std::vector<char>(static_cast<std::size_t>(count)), MPI_REQUEST_NULL});
      check(MPI_Imrecv(receives.back().bytes.data(), count, MPI_CHAR, &m, &receives.back().request), "MPI_Imrecv");
    }
    drop_completed(receives, deliver);
    if (!wait || !d.lines.empty() || d.done > 0) return d;
    if (receives.empty()) {
      MPI_Status status;
      check(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
    } else {
      check(MPI_Wait(&receives.front().request, MPI_STATUS_IGNORE), "MPI_Wait");
      deliver(receives.front());
      receives.pop_front();
    }
  }
}

void process_group::abort(int status) {
  if (state_->joined) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

bool built_with_mpi() { return true; }

}  // namespace rotlie::app
