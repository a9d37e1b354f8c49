#pragma once
// Moments of inertia of a rigid body as exact rationals: named bodies, parsing and the
// physical checks (positive, and the triangle inequalities of eq. 77).
#include <cln/rational.h>

#include <array>
#include <string>
#include <string_view>

namespace rotlie::lie {

struct moments_of_inertia {
  std::array<cln::cl_RA, 3> I;  ///< I1, I2, I3
};

/// "water" (10220/29376, 19187/29376, 1; LV section 4.3, Eisenberg & Kauzmann), "sphere" (1, 1, 1),
/// or "I1,I2,I3" with each value exact (see parse_exact_number). Throws std::invalid_argument with a
/// one-line reason: malformed value, not positive, or a violated triangle inequality.
moments_of_inertia parse_moments(std::string_view text);

/// Throws std::invalid_argument naming the broken rule.
void validate_moments(const moments_of_inertia& m);

/// The moments as exact text, "p/q p/q p/q" (a scheme table's `inertia` line): the form the
/// numeric side reads into its scalar with one rounding per moment (models::moments_from_text).
std::string inertia_text(const moments_of_inertia& m);

/// Which pair of moments coincide, e.g. "I1 = I2", or empty for an asymmetric body.
std::string symmetry_of(const moments_of_inertia& m);

}  // namespace rotlie::lie
