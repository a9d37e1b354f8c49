#pragma once
// Stopping a long symbolic computation from another thread (Python's Ctrl-C). GiNaC and CLN cannot
// be interrupted inside one operation, so the long loops offer points between units of work (a
// system solved, a stage of a nested BCH, a degree of a series, a body of a map): the caller
// installs a flag for its thread with stop_scope, and stop_point() throws `stopped` there once the
// flag is set. With no scope installed (the CLI, the report) a stop point costs one load.
#include <atomic>

namespace rotlie::lie {

/// Thrown by stop_point() when the current thread was asked to stop: the work's result is gone.
/// Deliberately not a std::exception: the places that turn a failure into a result (a map line
/// that says "failed", a system reported as not polished) must not swallow a stop.
struct stopped {};

/// While alive, stop_point() on this thread throws once `flag` is true. Scopes nest.
class stop_scope {
 public:
  explicit stop_scope(const std::atomic<bool>& flag);
  ~stop_scope();
  stop_scope(const stop_scope&) = delete;
  stop_scope& operator=(const stop_scope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

/// Throws stopped when the current thread's stop_scope flag is set.
void stop_point();

}  // namespace rotlie::lie
