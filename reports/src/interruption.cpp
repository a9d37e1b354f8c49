#include "rotlie/reports/interruption.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <cstring>

#include "rotlie/reports/child_process.hpp"
#include "rotlie/reports/output_file.hpp"

namespace rotlie::reports {
namespace {

constexpr std::array<int, 3> handled{SIGINT, SIGTERM, SIGHUP};
std::array<struct sigaction, 3> previous{};

void say(const char* text) {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = ::write(2, text, left);
    if (n <= 0) return;
    text += n, left -= static_cast<std::size_t>(n);
  }
}

// Only async-signal-safe calls from here on.
void on_stop_signal(int sig) {
  kill_running_child();
  remove_pending_temporaries();
  say(sig == SIGINT ? "rotlie: error: interrupted (SIGINT); files already written are complete\n"
      : sig == SIGTERM ? "rotlie: error: terminated (SIGTERM); files already written are complete\n"
                       : "rotlie: error: hung up (SIGHUP); files already written are complete\n");
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // delivered when the handler returns: the process ends by this signal
}

}  // namespace

interruption_guard::interruption_guard() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (const int s : handled) sigaddset(&action.sa_mask, s);  // one handler at a time
  for (std::size_t i = 0; i < handled.size(); ++i) {
    ::sigaction(handled[i], nullptr, &previous[i]);
    // A signal ignored by whoever started us (nohup, a background job) stays ignored.
    if (previous[i].sa_handler != SIG_IGN) ::sigaction(handled[i], &action, nullptr);
  }
}

interruption_guard::~interruption_guard() {
  for (std::size_t i = 0; i < handled.size(); ++i) ::sigaction(handled[i], &previous[i], nullptr);
}

}  // namespace rotlie::reports
