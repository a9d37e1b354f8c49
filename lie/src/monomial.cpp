#include "rotlie/lie/monomial.hpp"

namespace rotlie::lie {

std::string to_string(const monomial& m) {
  std::string s;
  for (int i = 0; i < 3; ++i) {
    if (m[i] == 0) continue;
    if (!s.empty()) s += '*';
    s += "G" + std::to_string(i + 1);
    if (m[i] > 1) s += "^" + std::to_string(m[i]);
  }
  return s.empty() ? "1" : s;
}

std::string compact_text(const monomial& m) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    if (m[i] > 0) s += "G" + std::to_string(i + 1) + "^" + std::to_string(m[i]);
  return s;
}

}  // namespace rotlie::lie
