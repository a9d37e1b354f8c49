#include "rotlie/schemes/same_body.hpp"

#include "rotlie/schemes/decimal_text.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rotlie::schemes {
namespace {

using decimal = decimal_number;

decimal times(const decimal& a, const decimal& b) {
  std::vector<int> r(a.digits.size() + b.digits.size(), 0);  // least significant first
  for (std::size_t i = 0; i < a.digits.size(); ++i)
    for (std::size_t j = 0; j < b.digits.size(); ++j)
      r[i + j] += (a.digits[a.digits.size() - 1 - i] - '0') * (b.digits[b.digits.size() - 1 - j] - '0');
  for (std::size_t k = 0; k + 1 < r.size(); ++k) r[k + 1] += r[k] / 10, r[k] %= 10;
  std::string d;
  for (std::size_t k = r.size(); k-- > 0;) d += static_cast<char>('0' + r[k]);
  return normalised_decimal(d, a.exponent + b.exponent);
}

bool operator==(const decimal& a, const decimal& b) { return a.digits == b.digits && a.exponent == b.exponent; }

struct fraction {
  decimal num, den;
};

std::optional<fraction> positive_fraction(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  const auto slash = s.find('/');
  const auto num = positive_decimal(s.substr(0, slash));
  const auto den = slash == std::string_view::npos ? positive_decimal("1") : positive_decimal(s.substr(slash + 1));
  if (!num || !den) return std::nullopt;
  return fraction{*num, *den};
}

std::vector<std::string> recorded_body(const scheme_table& t) {
  std::istringstream in(t.inertia);
  std::vector<std::string> parts;
  for (std::string p; in >> p;) parts.push_back(p);
  if (parts.size() != 3) throw std::invalid_argument("scheme table " + t.name + ": the inertia line is not three numbers");
  return parts;
}

// a_i / a_3 = b_i / b_3 with a = p/q: p_i q_3 P_3 Q_i = P_i Q_3 p_3 q_i.
bool same_ratio(const fraction& ai, const fraction& a3, const fraction& bi, const fraction& b3) {
  return times(times(ai.num, a3.den), times(b3.num, bi.den)) == times(times(bi.num, b3.den), times(a3.num, ai.den));
}

long double value_of(const std::string& text) {
  const auto slash = text.find('/');
  const long double num = std::strtold(text.substr(0, slash).c_str(), nullptr);
  const long double den = slash == std::string::npos ? 1.0L : std::strtold(text.substr(slash + 1).c_str(), nullptr);
  return num / den;
}

}  // namespace

bool is_body_text(std::string_view text) {
  std::istringstream in{std::string(text)};
  int n = 0;
  for (std::string p; in >> p; ++n)
    if (!positive_fraction(p)) return false;
  return n == 3;
}

body_match same_body(const scheme_table& t, const std::array<std::string_view, 3>& body) {
  std::array<fraction, 3> given;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto f = positive_fraction(body[i]);
    if (!f) throw std::invalid_argument("I" + std::to_string(i + 1) + " is not a positive exact number");
    given[i] = *f;
  }
  if (t.inertia.empty()) return body_match::unrecorded;
  const auto parts = recorded_body(t);
  std::array<fraction, 3> recorded;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto f = positive_fraction(parts[i]);
    if (!f) throw std::invalid_argument("scheme table " + t.name + ": inertia value '" + parts[i] + "' is not a positive number");
    recorded[i] = *f;
  }
  const bool same = same_ratio(recorded[0], recorded[2], given[0], given[2]) && same_ratio(recorded[1], recorded[2], given[1], given[2]);
  return same ? body_match::same : body_match::different;
}

body_match same_body(const scheme_table& t, const std::array<double, 3>& body, double relative) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!(std::isfinite(body[i]) && body[i] > 0))
      throw std::invalid_argument("I" + std::to_string(i + 1) + " is not a finite positive number");
  if (t.inertia.empty()) return body_match::unrecorded;
  const auto parts = recorded_body(t);
  const long double r3 = value_of(parts[2]);
  for (std::size_t i = 0; i < 2; ++i) {
    // ratios in long double: the table's values may lie far outside double's range
    const long double recorded = value_of(parts[i]) / r3;
    const long double given = static_cast<long double>(body[i]) / static_cast<long double>(body[2]);
    if (!(std::fabs(recorded - given) <= static_cast<long double>(relative) * std::fmax(recorded, given))) return body_match::different;
  }
  return body_match::same;
}

}  // namespace rotlie::schemes
