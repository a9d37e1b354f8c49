#pragma once
// What every harness checks besides the absence of crashes: stated properties (abort with the
// property's name, which libFuzzer reports as a crash with the input saved) and one-line refusals.
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace rotlie::fuzz {

inline void require(bool ok, const char* property) {
  if (!ok) {
    std::fprintf(stderr, "property violated: %s\n", property);
    std::abort();
  }
}

/// A refusal message is one line: no control characters (user bytes are shown as \xHH).
inline bool one_line(std::string_view message) {
  if (message.empty()) return false;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) return false;
  }
  return true;
}

}  // namespace rotlie::fuzz
