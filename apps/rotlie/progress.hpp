#pragma once
// Progress lines on stderr for long runs, shown only when stderr is a terminal so that logs
// and pipes stay clean.
#include <unistd.h>

#include <cstdio>
#include <string_view>

namespace rotlie::app {

class progress_line {
 public:
  progress_line() : enabled_(::isatty(2) == 1) {}
  ~progress_line() {
    if (enabled_ && shown_) std::fputs("\r\033[K", stderr);
  }
  progress_line(const progress_line&) = delete;
  progress_line& operator=(const progress_line&) = delete;
  void show(std::string_view text) {
    if (!enabled_) return;
    std::fprintf(stderr, "\r\033[K%.*s", static_cast<int>(text.size()), text.data());
    std::fflush(stderr);
    shown_ = true;
  }

 private:
  bool enabled_;
  bool shown_ = false;
};

}  // namespace rotlie::app
