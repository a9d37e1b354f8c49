#pragma once
// Running the rotlie binary from a CLI test: one scratch folder per test process, the command's
// stdout and stderr captured in it, the exit status (128 + n for a signal n, so a crash never
// passes for an error exit). ROTLIE_BINARY is the built binary's path, defined per test (CLI);
// include after boost/test/unit_test.hpp (the folder is removed by a global fixture).
#include <errno.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace rotlie::test_cli {

namespace fs = std::filesystem;

struct run_result {
  int status = -1;  ///< exit status, or 128 + signal
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// This test process's scratch folder (created on first use; the tests remove what they must).
inline const fs::path& scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() /
                       ("rotlie-" + std::string(program_invocation_short_name) + "-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

/// A shell command with stdin closed and both outputs captured.
inline run_result run_command(const std::string& command) {
  const fs::path out = scratch() / "stdout", err = scratch() / "stderr";
  const int raw = std::system((command + " >" + out.string() + " 2>" + err.string() + " </dev/null").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), slurp(out), slurp(err)};
}

/// rotlie with the given arguments (shell words).
inline run_result run(const std::string& args) { return run_command(std::string(ROTLIE_BINARY) + " " + args); }

/// A refused input: exit 2, nothing on stdout, one line on stderr that mentions `must_mention`.
inline void expect_refusal(const std::string& args, const std::string& must_mention) {
  const auto r = run(args);
  BOOST_TEST_CONTEXT("rotlie " << args << " → " << r.status << ": " << r.err) {
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.out.empty());
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    BOOST_TEST(r.err.find(must_mention) != std::string::npos);
  }
}

/// rotlie started in the background (its outputs discarded), killed by SIGKILL and reaped when the
/// object goes: for a run that must be going on while another command is tried.
class background_run {
 public:
  explicit background_run(const std::string& args) {
    pid_ = ::fork();
    if (pid_ == 0) {
      const std::string command = "exec " + std::string(ROTLIE_BINARY) + " " + args + " >/dev/null 2>&1 </dev/null";
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
  }
  ~background_run() { stop(); }
  background_run(const background_run&) = delete;
  background_run& operator=(const background_run&) = delete;
  /// Whether the run is still going (it has not exited by itself).
  bool running() {
    if (pid_ <= 0) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == 0) return true;
    pid_ = -1;
    return false;
  }
  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
};

/// Removes the scratch folder when the test process ends.
struct scratch_cleanup {
  ~scratch_cleanup() {
    std::error_code ec;
    fs::remove_all(scratch(), ec);
  }
};

}  // namespace rotlie::test_cli

using rotlie_cli_scratch_cleanup = rotlie::test_cli::scratch_cleanup;
BOOST_TEST_GLOBAL_FIXTURE(rotlie_cli_scratch_cleanup);
