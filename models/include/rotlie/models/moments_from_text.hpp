#pragma once
// A body's moments of inertia read once, from exact text, into the scalar in use: the form of a
// scheme table's `inertia` line ("10220/29376 19187/29376 1"), each moment p or p/q with p and q
// decimals ([+]digits[.digits][e±digits]). p and q are each read at the full precision of T and
// divided once, so a float128 run sees the rational rounded to float128, never a double first.
#include <cctype>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/rigid_body.hpp"
#include "rotlie/schemes/decimal_text.hpp"

namespace rotlie::models {

namespace detail {

using decimal_text = schemes::decimal_number;

/// d / 10^(digits − 1): the same digits with the point after the first, in [1, 10).
template <class T>
T leading_part(const decimal_text& d) {
  return parse_scalar<T>(d.digits.substr(0, 1) + "." + d.digits.substr(1) + "0");
}

/// p/q in T: each read correctly rounded and divided once. When p or q alone is outside T's range
/// (a table may write 400-digit integers) the quotient is formed from their leading parts and the
/// power of ten between them instead.
template <class T>
T quotient(const decimal_text& p, const decimal_text& q, const std::string& text_p, const std::string& text_q) {
  using std::isfinite;  // float128's by argument-dependent lookup
  const T a = parse_scalar<T>(text_p), b = parse_scalar<T>(text_q);
  if (isfinite(a) && isfinite(b) && a > 0 && b > 0) return a / b;
  const long shift = (p.exponent + static_cast<long>(p.digits.size())) - (q.exponent + static_cast<long>(q.digits.size()));
  return leading_part<T>(p) / leading_part<T>(q) * parse_scalar<T>("1e" + std::to_string(shift));
}

}  // namespace detail

/// One moment, p or p/q; throws std::invalid_argument unless it is a positive exact number of
/// that form whose value is finite and positive in T.
template <class T>
T moment_from_text(std::string_view text) {
  const auto slash = text.find('/');
  const std::string p_text(text.substr(0, slash));
  const std::string q_text = slash == std::string_view::npos ? std::string("1") : std::string(text.substr(slash + 1));
  const auto p = schemes::positive_decimal(p_text), q = schemes::positive_decimal(q_text);
  if (!p || !q)
    throw std::invalid_argument("a moment of inertia must be a positive exact number (p or p/q), got '" + std::string(text) + "'");
  const T x = detail::quotient<T>(*p, *q, p_text, q_text);
  using std::isfinite;
  if (!(x > 0) || !isfinite(static_cast<double>(x)))
    throw std::invalid_argument("the moment of inertia '" + std::string(text) + "' is outside the range of the scalar");
  return x;
}

/// Three moments separated by blanks (a table's `inertia` line), validated (eq. 77).
template <class T>
vec3<T> moments_from_text(const std::string& text) {
  std::istringstream in(text);
  vec3<T> I{};
  std::string part;
  for (auto& x : I) {
    if (!(in >> part)) throw std::invalid_argument("three moments of inertia are needed, got '" + text + "'");
    x = moment_from_text<T>(part);
  }
  if (in >> part) throw std::invalid_argument("three moments of inertia are needed, got '" + text + "'");
  validate_moments(I);
  return I;
}

}  // namespace rotlie::models
