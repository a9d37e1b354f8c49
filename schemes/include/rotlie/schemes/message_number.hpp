#pragma once
// A number in a message or a progress line: six significant digits, no trailing zeros ("0.5 ps",
// "|t| ≤ 2.3e+14"), as a reader writes it; std::to_string would say 0.500000 or 0.000000.
#include <sstream>
#include <string>

namespace rotlie::schemes {

inline std::string message_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace rotlie::schemes
