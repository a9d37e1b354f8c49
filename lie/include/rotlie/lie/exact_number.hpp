#pragma once
// Exact rationals from user text — "3", "-1/3", "10220/29376", "0.348", "3.48e-1" — parsed by
// hand, never by GiNaC's parser (which crashes on some malformed input).
#include <cln/rational.h>

#include <optional>
#include <string>
#include <string_view>

#include "rotlie/schemes/printable_text.hpp"

namespace rotlie::lie {

/// Limits on user numbers: at most this many digits in a decimal and in the numerator and the
/// denominator of the value in lowest terms (so that the exact p/q text of every accepted value is
/// accepted too), and a magnitude of 0 or within 10^-max_decimal_exponent … 10^max_decimal_exponent
/// (for the whole value, fractions included).
inline constexpr std::size_t max_number_digits = 1000;
inline constexpr long max_decimal_exponent = 400;

struct parsed_number {
  std::optional<cln::cl_RA> value;
  std::string problem;  ///< why the text is not such a number (empty when value holds)
};

/// [+-]digits[.digits][(e|E)[+-]digits], optionally "/ another such decimal", surrounding blanks
/// ignored. Refused with a reason: malformed (also NaN, inf, hexadecimal), a zero denominator, too
/// many digits, a magnitude beyond the limits above.
parsed_number parse_exact_number_checked(std::string_view text);

/// The exact value, or nothing when parse_exact_number_checked refuses the text.
std::optional<cln::cl_RA> parse_exact_number(std::string_view text);

/// Decimal text of an exact rational with `digits` ≥ 1 significant digits (rounded to nearest);
/// parse_exact_number reads it back within half a unit of its last digit.
std::string to_decimal(const cln::cl_RA& x, int digits);

/// User text fit for a one-line message (one rule for every parser: schemes/printable_text.hpp).
using schemes::printable_text;

}  // namespace rotlie::lie
