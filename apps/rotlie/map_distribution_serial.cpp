// process_group without MPI: this process alone.
#include <cstdlib>
#include <stdexcept>

#include "map_distribution.hpp"

namespace rotlie::app {

struct process_group::state {};

process_group::process_group() = default;
process_group::~process_group() = default;
int process_group::rank() const { return 0; }
int process_group::size() const { return 1; }
std::string process_group::broadcast(const std::string& from_rank0) { return from_rank0; }
void process_group::send_results(const std::vector<std::pair<std::size_t, std::string>>&) {
  throw std::logic_error("no other process to send to");
}
void process_group::send_done() {}
process_group::delivery process_group::receive(bool) { return {}; }
void process_group::abort(int status) { std::exit(status); }
bool built_with_mpi() { return false; }

}  // namespace rotlie::app
