#include "interruption.hpp"

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "rotlie/lie/stop_request.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;
using namespace std::chrono_literals;

constexpr auto poll_interval = 50ms;  // the longest a Ctrl-C waits to be seen
constexpr auto stop_grace = 500ms;    // the longest an interrupted symbolic call waits for its stop point

// One finished-or-not flag with the work's exception, shared by the worker and the waiting caller.
struct completion {
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr error;

  void finish(std::exception_ptr e) {
    std::lock_guard lock(m);
    done = true;
    error = std::move(e);
    cv.notify_all();
  }
  bool wait_for(std::chrono::milliseconds d) {
    std::unique_lock lock(m);
    return cv.wait_for(lock, d, [this] { return done; });
  }
  /// Runs f on the worker, handing over its exception (or none).
  template <class F>
  void run(F&& f) {
    try {
      f();
      finish(nullptr);
    } catch (...) {
      finish(std::current_exception());
    }
  }
};

// True when a Python signal handler raised (the Python error is then set). Takes the GIL.
bool interrupted() {
  py::gil_scoped_acquire gil;
  return PyErr_CheckSignals() != 0;
}

// Every symbolic computation holds this while it runs, an abandoned one too.
std::mutex& symbolic_mutex() {
  static auto* m = new std::mutex;  // never destroyed: an abandoned worker may still hold it at exit
  return *m;
}

// At exit an abandoned symbolic computation must not meet the libraries' static destructors: wait
// for it to end (the process exits once it has).
void wait_for_abandoned_work() { std::lock_guard lock(symbolic_mutex()); }

// Waits in slices until the work is done (false) or a Python signal handler raised (true).
bool interrupted_while_waiting(completion& state) {
  while (!state.wait_for(poll_interval))
    if (interrupted()) return true;
  return false;
}

}  // namespace

void run_cancellable(const std::function<void(const cancellation&)>& work) {
  cancellation cancel;
  auto state = std::make_shared<completion>();
  bool was_interrupted = false;
  {
    py::gil_scoped_release nogil;
    std::thread worker([&work, &cancel, state] { state->run([&] { work(cancel); }); });
    was_interrupted = interrupted_while_waiting(*state);
    if (was_interrupted) cancel.request();
    worker.join();  // a cancelled loop stops within one slice of its work
  }
  if (was_interrupted) throw py::error_already_set();
  if (state->error) std::rethrow_exception(state->error);
}

void run_symbolic(std::function<void()> work) {
  static const bool registered = [] { return std::atexit(wait_for_abandoned_work) == 0; }();
  (void)registered;
  auto state = std::make_shared<completion>();
  auto stop = std::make_shared<std::atomic<bool>>(false);  // outlives an abandoned worker
  bool was_interrupted = false;
  {
    py::gil_scoped_release nogil;
    std::thread worker([work = std::move(work), state, stop] {
      std::lock_guard lock(symbolic_mutex());
      const lie::stop_scope scope(*stop);
      state->run(work);
    });
    was_interrupted = interrupted_while_waiting(*state);
    if (was_interrupted) {
      // The work stops at its next stop point (lie/stop_request.hpp); wait a little for it, and
      // abandon it only if that point is further away.
      stop->store(true);
      if (state->wait_for(stop_grace))
        worker.join();
      else
        worker.detach();
    } else {
      worker.join();
    }
  }
  if (was_interrupted) throw py::error_already_set();
  if (state->error) std::rethrow_exception(state->error);
}

}  // namespace rotlie::python
