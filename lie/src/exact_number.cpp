#include "rotlie/lie/exact_number.hpp"

#include <cln/integer.h>
#include <cln/integer_io.h>

#include <cctype>
#include <sstream>
#include <stdexcept>

namespace rotlie::lie {
namespace {

// cln::expt_pos needs a positive exponent.
cln::cl_I power_of_ten(long n) { return n == 0 ? cln::cl_I(1) : cln::expt_pos(cln::cl_I(10), static_cast<unsigned int>(n)); }

const std::string range_problem = "is beyond the supported range (a magnitude between 1e-" +
                                  std::to_string(max_decimal_exponent) + " and 1e" +
                                  std::to_string(max_decimal_exponent) + ", or 0)";
const std::string syntax_problem = "is not a finite number (use e.g. 0.348, 3.48e-1 or 10220/29376)";

// numerator and denominator in lowest terms below 10^max_number_digits
bool small_enough(const cln::cl_RA& x) {
  static const cln::cl_I bound = power_of_ten(static_cast<long>(max_number_digits));
  return cln::abs(cln::numerator(x)) < bound && cln::denominator(x) < bound;
}

bool in_range(const cln::cl_RA& x) {
  if (cln::zerop(x)) return true;
  const cln::cl_RA a = cln::abs(x), bound = power_of_ten(max_decimal_exponent);
  return a <= bound && a * bound >= 1;
}

// [+-]digits[.digits][(e|E)[+-]digits]
parsed_number parse_decimal(std::string_view s) {
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  std::string digits;  // leading zeros dropped
  long scale = 0;
  std::size_t count = 0;
  bool seen_point = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (std::isdigit(static_cast<unsigned char>(c))) {
      if (++count > max_number_digits) return {std::nullopt, "has more than " + std::to_string(max_number_digits) + " digits"};
      if (!(digits.empty() && c == '0')) digits += c;
      if (seen_point) --scale;
    } else if (c == '.' && !seen_point) {
      seen_point = true;
    } else {
      break;
    }
  }
  if (count == 0) return {std::nullopt, syntax_problem};
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative_exponent = s[i++] == '-';
    const std::size_t start = i;
    long e = 0;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      if (e <= 10 * max_decimal_exponent) e = e * 10 + (s[i] - '0');  // saturates far beyond any accepted value
    if (i == start) return {std::nullopt, syntax_problem};
    scale += negative_exponent ? -e : e;
  }
  if (i != s.size()) return {std::nullopt, syntax_problem};
  if (digits.empty()) return {cln::cl_RA(0), ""};
  // Leading digit at 10^(size − 1 + scale): refuse before building a huge power of ten. The bound
  // is loose, as one part of p/q may lie beyond the range that the quotient meets (1e1000/1e999).
  const long leading = static_cast<long>(digits.size()) - 1 + scale;
  const long loose = max_decimal_exponent + static_cast<long>(max_number_digits);
  if (leading > loose || leading < -loose) return {std::nullopt, range_problem};
  cln::cl_I mantissa = 0;
  for (const char c : digits) mantissa = mantissa * 10 + (c - '0');
  if (negative) mantissa = -mantissa;
  if (scale >= 0) return {cln::cl_RA(mantissa * power_of_ten(scale)), ""};
  return {cln::cl_RA(mantissa) / cln::cl_RA(power_of_ten(-scale)), ""};
}

}  // namespace

parsed_number parse_exact_number_checked(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (text.empty()) return {std::nullopt, "is empty"};
  const auto slash = text.find('/');
  parsed_number out;
  if (slash == std::string_view::npos) {
    out = parse_decimal(text);
  } else {
    const auto num = parse_decimal(text.substr(0, slash));
    if (!num.value) return num;
    const auto den = parse_decimal(text.substr(slash + 1));
    if (!den.value) return den;
    if (cln::zerop(*den.value)) return {std::nullopt, "has a zero denominator"};
    out.value = *num.value / *den.value;
  }
  if (out.value && !in_range(*out.value)) return {std::nullopt, range_problem};
  if (out.value && !small_enough(*out.value))
    return {std::nullopt, "has a numerator or denominator of more than " + std::to_string(max_number_digits) + " digits in lowest terms"};
  return out;
}

std::optional<cln::cl_RA> parse_exact_number(std::string_view text) { return parse_exact_number_checked(text).value; }

std::string to_decimal(const cln::cl_RA& x, int digits) {
  if (digits < 1) throw std::invalid_argument("to_decimal: digits must be at least 1");
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
