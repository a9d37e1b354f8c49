#include "rotlie/lie/stop_request.hpp"

namespace rotlie::lie {
namespace {

thread_local const std::atomic<bool>* current_flag = nullptr;

}  // namespace

stop_scope::stop_scope(const std::atomic<bool>& flag) : previous_(current_flag) { current_flag = &flag; }

stop_scope::~stop_scope() { current_flag = previous_; }

void stop_point() {
  if (current_flag && current_flag->load(std::memory_order_relaxed)) throw stopped();
}

}  // namespace rotlie::lie
