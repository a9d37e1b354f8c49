#pragma once
// A body as a user names it: three exact moments "I1,I2,I3" (decimals or rationals), or a name
// (water, sphere), checked against the set of rigid bodies (eq. 77).
#include <string>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

/// The range of every scale the numeric runs take (moments, |G0|, h, T, and the angular rate
/// |G0|/I): inside it no product or quotient of two of them leaves double precision.
inline constexpr int max_decimal_exponent = 150;

/// Exact moments, required (the solving commands): throws bad_input for empty or bad text.
lie::moments_of_inertia required_body(const std::string& text);

/// Exact moments of any size (the exact commands: remainder); a moment written as a number beyond
/// the exact parser's limits is "out of range". Throws bad_input.
lie::moments_of_inertia exact_body(const std::string& text);

/// The same, each moment within 1e-150 … 1e150 (the numeric commands). Throws bad_input.
lie::moments_of_inertia numeric_body(const std::string& text);

/// The moments rounded once each to double.
models::vec3<double> to_double(const lie::moments_of_inertia& body);

}  // namespace rotlie::runs
