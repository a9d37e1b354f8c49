#include "rotlie/reports/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <tuple>
#include <utility>

extern char** environ;

namespace rotlie::reports {
namespace {

std::atomic<pid_t> running_child{0};
constexpr std::size_t stderr_limit = 64 * 1024;
constexpr std::size_t stdout_limit = 256 * 1024 * 1024;

// The signals after which rotlie stops (and kills the child): blocked while the child's pid
// is being recorded or cleared, so that the handler never sees a stale pid.
sigset_t stopping_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
  return set;
}

class blocked_signals {
 public:
  explicit blocked_signals(const sigset_t& set) { pthread_sigmask(SIG_BLOCK, &set, &previous_); }
  ~blocked_signals() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  blocked_signals(const blocked_signals&) = delete;
  blocked_signals& operator=(const blocked_signals&) = delete;

 private:
  sigset_t previous_;
};

struct pipe_pair {
  int read = -1, write = -1;
  pipe_pair() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    read = fds[0], write = fds[1];
  }
  ~pipe_pair() {
    close_read();
    close_write();
  }
  pipe_pair(const pipe_pair&) = delete;
  pipe_pair& operator=(const pipe_pair&) = delete;
  void close_read() {
    if (read >= 0) ::close(std::exchange(read, -1));
  }
  void close_write() {
    if (write >= 0) ::close(std::exchange(write, -1));
  }
};

pid_t spawn(const std::vector<std::string>& argv, pipe_pair& in, pipe_pair& out, pipe_pair& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.read, 0);
  posix_spawn_file_actions_adddup2(&actions, out.write, 1);
  posix_spawn_file_actions_adddup2(&actions, err.write, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  // Its own process group, so that killing it also ends anything it started.
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);

  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, args[0], &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0) throw child_start_error(argv[0], error);
  return pid;
}

double seconds_since(const timespec& start) {
  timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec - start.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec - start.tv_nsec);
}

// Feeds the input and drains both outputs until the child closes them or the limit passes.
// Returns false on timeout.
bool exchange(pipe_pair& in, pipe_pair& out, pipe_pair& err, std::string_view input, child_result& r,
              const timespec& start, std::chrono::seconds limit) {
  ::fcntl(in.write, F_SETFL, O_NONBLOCK);
  if (input.empty()) in.close_write();
  std::array<char, 65536> buffer;
  while (out.read >= 0 || err.read >= 0) {
    const double left = static_cast<double>(limit.count()) - seconds_since(start);
    if (left <= 0) return false;
    std::array<pollfd, 3> fds{pollfd{in.write, POLLOUT, 0}, pollfd{out.read, POLLIN, 0}, pollfd{err.read, POLLIN, 0}};
    if (::poll(fds.data(), fds.size(), static_cast<int>(left * 1000) + 1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("cannot wait for a child process: ") + std::strerror(errno));
    }
    if (in.write >= 0 && fds[0].revents) {
      const ssize_t n = ::write(in.write, input.data(), input.size());
      if (n > 0) input.remove_prefix(static_cast<std::size_t>(n));
      if ((n < 0 && errno != EAGAIN && errno != EINTR) || input.empty()) in.close_write();  // EPIPE: it stopped reading
    }
    for (auto [fd, pipe, text, cap] : {std::tuple{fds[1], &out, &r.out, stdout_limit},
                                       std::tuple{fds[2], &err, &r.err, stderr_limit}}) {
      if (pipe->read < 0 || !fd.revents) continue;
      const ssize_t n = ::read(pipe->read, buffer.data(), buffer.size());
      if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) pipe->close_read();
      if (n > 0) text->append(buffer.data(), std::min(static_cast<std::size_t>(n), cap - std::min(cap, text->size())));
    }
  }
  return true;
}

// Waits, within the limit, until the child has exited, without reaping it (its pid stays ours
// while a signal handler may still kill it). Returns false on timeout.
bool exited_in_time(pid_t pid, const timespec& start, std::chrono::seconds limit) {
  for (;;) {
    siginfo_t info{};
    const int rc = ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT | WNOHANG);
    if (rc == 0 && info.si_pid != 0) return true;
    if (rc != 0 && errno != EINTR) return true;  // nothing to wait for: waitpid reports it
    if (seconds_since(start) > static_cast<double>(limit.count())) return false;
    const timespec pause{0, 5'000'000};
    ::nanosleep(&pause, nullptr);
  }
}

}  // namespace

child_start_error::child_start_error(const std::string& program, int e)
    : std::runtime_error("cannot run " + program + ": " + std::strerror(e)), error(e) {}

child_result run_child(const std::vector<std::string>& argv, std::string_view input, std::chrono::seconds limit) {
  pipe_pair in, out, err;
  // A child that stops reading must give EPIPE here, not end rotlie with SIGPIPE.
  sigset_t pipe_signal;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  blocked_signals no_sigpipe(pipe_signal);

  pid_t pid = 0;
  {
    const blocked_signals hold(stopping_signals());
    pid = spawn(argv, in, out, err);
    running_child.store(pid);
  }
  in.close_read(), out.close_write(), err.close_write();

  child_result r;
  timespec start;
  clock_gettime(CLOCK_MONOTONIC, &start);
  try {
    // A child may also close its outputs and go on running: the limit holds for its exit too.
    r.timed_out = !exchange(in, out, err, input, r, start, limit) || !exited_in_time(pid, start, limit);
  } catch (...) {
    kill_running_child();
    throw;
  }
  in.close_write();
  if (r.timed_out) ::kill(-pid, SIGKILL);
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
  }
  int status = 0;
  {
    const blocked_signals hold(stopping_signals());
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    running_child.store(0);
  }
  // Discard a SIGPIPE raised by a write to the closed pipe before unblocking it.
  const timespec zero{0, 0};
  while (sigtimedwait(&pipe_signal, nullptr, &zero) == SIGPIPE) {
  }
  if (WIFEXITED(status)) r.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

void kill_running_child() noexcept {
  const pid_t pid = running_child.exchange(0);
  if (pid <= 0) return;
  ::kill(-pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace rotlie::reports
