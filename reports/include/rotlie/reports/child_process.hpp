#pragma once
// Runs a helper program (gnuplot) without a shell: the arguments go to execvp as they are, the
// input is written to the child's stdin and its stdout and stderr are collected in memory, so
// no user text is ever interpreted by a shell. One child runs at a time; a signal handler can
// stop it with kill_running_child().
#include <chrono>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rotlie::reports {

struct child_result {
  int exit_status = -1;    ///< the child's exit status, or -1 when it was ended by a signal
  int signal = 0;          ///< the signal that ended it, or 0
  bool timed_out = false;  ///< killed by us after the time limit
  std::string out, err;    ///< what it wrote (stderr is kept up to its first 64 KiB)
};

/// The program could not be started; `error` is the errno (ENOENT: not installed).
struct child_start_error : std::runtime_error {
  child_start_error(const std::string& program, int error);
  int error;
};

/// Runs argv[0] (looked up on PATH) with argv, `input` on its stdin, until it exits or the time
/// limit passes (then it is killed and `timed_out` is set). Signals that end rotlie are reset
/// to their defaults in the child. Throws child_start_error when it cannot start.
child_result run_child(const std::vector<std::string>& argv, std::string_view input, std::chrono::seconds limit);

/// Kills and reaps the running child, if any. Async-signal-safe.
void kill_running_child() noexcept;

}  // namespace rotlie::reports
