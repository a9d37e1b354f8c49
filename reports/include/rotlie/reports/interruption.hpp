#pragma once
// What SIGINT (Ctrl-C), SIGTERM and SIGHUP do during a report: kill gnuplot if it runs, remove
// the temporary being written, say so on stderr, then end the process by the same signal, so
// that the caller sees an interrupted run (status 128 + n: 130 for Ctrl-C, 143 for SIGTERM).
// Files already renamed into place are complete; nothing half-written remains.
#include <boost/core/noncopyable.hpp>

namespace rotlie::reports {

/// Installs the handlers for its lifetime and restores the previous ones afterwards.
class interruption_guard : boost::noncopyable {
 public:
  interruption_guard();
  ~interruption_guard();
};

}  // namespace rotlie::reports
