#pragma once
// Exact rationals from user text — "3", "-1/3", "10220/29376", "0.348", "3.48e-1" — parsed by
// hand, never by GiNaC's parser (which crashes on some malformed input).
#include <cln/rational.h>

#include <optional>
#include <string>
#include <string_view>

namespace rotlie::lie {

/// The exact value, or nothing when the text is not such a number (also: NaN, inf, a zero
/// denominator, more than 400 digits, an exponent beyond ±400).
std::optional<cln::cl_RA> parse_exact_number(std::string_view text);

/// Decimal text of an exact rational with `digits` significant digits (rounded to nearest).
std::string to_decimal(const cln::cl_RA& x, int digits);

}  // namespace rotlie::lie
