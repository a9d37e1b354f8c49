#pragma once
// One rule for echoing user text in an error message, shared by every parser on both sides:
// header-only, so that the symbolic side (lie, bch) can use it without the scheme tables.
#include <cstddef>
#include <string>
#include <string_view>

namespace rotlie::schemes {

/// User text fit for a one-line message: bytes outside printable ASCII as \xHH, at most 80
/// characters (then "…").
inline std::string printable_text(std::string_view text) {
  constexpr std::size_t max_shown = 80;
  constexpr char hex[] = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < max_shown; ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u >= 0x20 && u < 0x7f)
      out += static_cast<char>(u);
    else
      out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
  }
  return text.size() > max_shown ? out + "…" : out;
}

}  // namespace rotlie::schemes
