#pragma once
// What SIGINT (Ctrl-C), SIGTERM and SIGHUP do during a report: kill gnuplot if it runs, remove
// the temporary being written, say so on stderr, then end the process by the same signal, so
// that the caller sees an interrupted run (status 128 + n: 130 for Ctrl-C, 143 for SIGTERM).
// Files already renamed into place are complete; nothing half-written remains.

namespace rotlie::reports {

/// Installs the handlers for its lifetime and restores the previous ones afterwards.
class interruption_guard {
 public:
  interruption_guard();
  ~interruption_guard();
  interruption_guard(const interruption_guard&) = delete;
  interruption_guard& operator=(const interruption_guard&) = delete;
};

}  // namespace rotlie::reports
