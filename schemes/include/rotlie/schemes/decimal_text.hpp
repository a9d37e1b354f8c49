#pragma once
// Positive decimal text ([+]digits[.digits][(e|E)[+-]digits]) as digits and a power of ten, for the
// exact readers of the numeric side (a table's `inertia` line is compared and read without a
// big-number library). One scanner, so that what one reader accepts the other accepts too.
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rotlie::schemes {

/// digits · 10^exponent, digits most significant first with no leading or trailing zeros ("0" only
/// for zero).
struct decimal_number {
  std::string digits;
  long exponent = 0;
};

inline constexpr std::size_t max_decimal_digits = 400;  ///< digits written, leading zeros included
inline constexpr long max_decimal_exponent = 400;       ///< |exponent| after e or E

inline decimal_number normalised_decimal(std::string digits, long exponent) {
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return {"0", 0};
  digits.erase(0, first);
  const auto last = digits.find_last_not_of('0');
  exponent += static_cast<long>(digits.size() - 1 - last);
  digits.erase(last + 1);
  return {digits, exponent};
}

/// The number, or nothing when the text is malformed, zero or beyond the limits above.
inline std::optional<decimal_number> positive_decimal(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && s[i] == '+') ++i;
  std::string digits;
  long exponent = 0;
  bool point = false;
  for (; i < s.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(s[i]))) {
      digits += s[i];
      if (point) --exponent;
    } else if (s[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (digits.empty() || digits.size() > max_decimal_digits) return std::nullopt;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    const bool negative = i < s.size() && s[i] == '-';
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t start = i;
    long e = 0;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      if ((e = e * 10 + (s[i] - '0')) > max_decimal_exponent) return std::nullopt;
    if (i == start) return std::nullopt;
    exponent += negative ? -e : e;
  }
  if (i != s.size()) return std::nullopt;
  const decimal_number d = normalised_decimal(digits, exponent);
  if (d.digits == "0") return std::nullopt;
  return d;
}

}  // namespace rotlie::schemes
