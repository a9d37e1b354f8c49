#include "rotlie/lie/exact_number.hpp"

#include <cln/integer.h>
#include <cln/integer_io.h>

#include <cctype>
#include <cstdlib>
#include <sstream>

namespace rotlie::lie {
namespace {

constexpr std::size_t max_digits = 400;
constexpr long max_exponent = 400;

// cln::expt_pos needs a positive exponent.
cln::cl_I power_of_ten(long n) { return n == 0 ? cln::cl_I(1) : cln::expt_pos(cln::cl_I(10), static_cast<unsigned int>(n)); }

// [+-]digits[.digits][(e|E)[+-]digits]
std::optional<cln::cl_RA> parse_decimal(std::string_view s) {
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  std::string digits;
  long scale = 0;
  bool seen_digit = false, seen_point = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      digits += c;
      seen_digit = true;
      if (seen_point) --scale;
    } else if (c == '.' && !seen_point) {
      seen_point = true;
    } else {
      break;
    }
  }
  if (!seen_digit || digits.size() > max_digits) return std::nullopt;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative_exponent = s[i++] == '-';
    const std::size_t start = i;
    long e = 0;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) {
      e = e * 10 + (s[i] - '0');
      if (e > max_exponent) return std::nullopt;
    }
    if (i == start) return std::nullopt;
    scale += negative_exponent ? -e : e;
  }
  if (i != s.size()) return std::nullopt;
  cln::cl_I mantissa = 0;
  for (const char c : digits) mantissa = mantissa * 10 + (c - '0');
  if (negative) mantissa = -mantissa;
  if (scale >= 0) return cln::cl_RA(mantissa * power_of_ten(scale));
  return cln::cl_RA(mantissa) / cln::cl_RA(power_of_ten(-scale));
}

}  // namespace

std::optional<cln::cl_RA> parse_exact_number(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (text.empty()) return std::nullopt;
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_decimal(text);
  const auto num = parse_decimal(text.substr(0, slash));
  const auto den = parse_decimal(text.substr(slash + 1));
  if (!num || !den || cln::zerop(*den)) return std::nullopt;
  return *num / *den;
}

std::string to_decimal(const cln::cl_RA& x, int digits) {
  if (cln::zerop(x)) return "0";
  const bool negative = cln::minusp(x);
  const cln::cl_RA a = negative ? -x : x;
  // exponent e with 10^e ≤ a < 10^(e+1)
  long e = 0;
  cln::cl_RA scaled = a;
  while (scaled >= 10) scaled = scaled / 10, ++e;
  while (scaled < 1) scaled = scaled * 10, --e;
  const cln::cl_I m = cln::round1(scaled * power_of_ten(digits - 1));
  std::ostringstream s;
  s << m;
  std::string d = s.str();
  if (static_cast<int>(d.size()) > digits) {  // rounding carried into a new digit (9.99… → 10.0…)
    d.pop_back();
    ++e;
  }
  std::string out = (negative ? "-" : "") + d.substr(0, 1);
  if (d.size() > 1) out += "." + d.substr(1);
  if (e != 0) out += "e" + std::to_string(e);
  return out;
}

}  // namespace rotlie::lie
