#include "rotlie/runs/user_input.hpp"

#include <charconv>

namespace rotlie::runs {

long integer_in_range(std::string_view text, std::string_view option, long lo, long hi) {
  const std::string name(option);
  const std::string shown(text);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || (ec != std::errc() && ec != std::errc::result_out_of_range) || end != digits.data() + digits.size())
    throw bad_input(name + ": '" + shown + "' is not an integer");
  const bool too_small = ec == std::errc::result_out_of_range ? digits.front() == '-' : value < lo;
  const bool too_large = ec == std::errc::result_out_of_range ? digits.front() != '-' : value > hi;
  if (too_small) throw bad_input(name + " must be at least " + std::to_string(lo) + ", got " + shown);
  if (too_large) throw bad_input(name + " must be at most " + std::to_string(hi) + ", got " + shown);
  return value;
}

std::string why_not_a_number(std::string_view text) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  for (const char* word : {"nan", "inf"})
    if (lower.find(word) != std::string::npos) return "is not a finite number";
  // [+-]digits[.digits][e[+-]digits], possibly over the limits of the exact parser
  std::size_t i = 0, mantissa_digits = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  bool point = false;
  for (; i < text.size() && ((text[i] >= '0' && text[i] <= '9') || (text[i] == '.' && !point)); ++i)
    if (text[i] == '.') point = true;
    else ++mantissa_digits;
  if (mantissa_digits == 0) return "is not a number";
  if (i == text.size()) return "is out of range (too many digits)";
  if (text[i] != 'e' && text[i] != 'E') return "is not a number";
  ++i;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t exponent_start = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  return i == text.size() && i > exponent_start ? "is out of range" : "is not a number";
}

std::string one_line(std::string_view message) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    else out += c;
  }
  return out;
}

}  // namespace rotlie::runs
