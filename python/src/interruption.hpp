#pragma once
// Long calls run with the GIL released and stay interruptible: the work runs on a worker thread
// while the calling thread waits in slices, taking the GIL between slices so that Python runs its
// signal handlers (Ctrl-C raises KeyboardInterrupt there). Numeric loops poll a cancellation flag.
// The symbolic side stops at its stop points (lie/stop_request.hpp, between units of work such as
// one system solved); GiNaC and CLN cannot be interrupted inside one operation, so work whose next
// point is further away runs on to it in the background, its result discarded, and the next symbolic
// call waits for it (GiNaC and CLN are not thread-safe).
#include <atomic>
#include <functional>

namespace rotlie::python {

/// Set when the caller was interrupted: a loop that polls it stops early (its result is discarded).
class cancellation {
 public:
  bool requested() const { return flag_.load(std::memory_order_relaxed); }
  void request() { flag_.store(true, std::memory_order_relaxed); }

 private:
  std::atomic<bool> flag_{false};
};

/// Runs `work` with the GIL released; returns when it is done, rethrowing its exception, or throws
/// pybind11::error_already_set (KeyboardInterrupt) within a fraction of a second of Ctrl-C, after
/// the work has seen the cancellation and stopped. Called with the GIL held.
void run_cancellable(const std::function<void(const cancellation&)>& work);

/// The same for symbolic work: on Ctrl-C it is asked to stop at its next stop point; if it has not
/// stopped within half a second it is abandoned (it runs on to that point in the background,
/// serialised with every other symbolic call). KeyboardInterrupt is raised within a second either
/// way. `work` must own everything it touches (capture by value).
void run_symbolic(std::function<void()> work);

}  // namespace rotlie::python
