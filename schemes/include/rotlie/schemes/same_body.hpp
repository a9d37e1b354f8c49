#pragma once
// Whether a scheme table was solved for a given body. A dedicated scheme's coefficients depend only
// on the ratios I1 : I2 : I3 (H_R3 is homogeneous in the moments), so bodies are compared up to a
// common positive factor: water in u Å² and water scaled to I3 = 1 are the same body.
#include <array>
#include <string>
#include <string_view>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::schemes {

enum class body_match {
  same,        ///< the recorded body, up to a common factor
  different,   ///< another body: the table's order is not guaranteed for it
  unrecorded,  ///< the table names no body (reference schemes work for every body)
};

/// Whether text is three positive exact numbers separated by blanks (a table's `inertia` line).
bool is_body_text(std::string_view text);

/// Exact: the table's `inertia` line and I1, I2, I3 as exact text (3, 0.348, 3.48e-1, 10220/29376;
/// at most 400 digits per decimal) are compared as rationals, I1·J3 = J1·I3 and I2·J3 = J2·I3.
/// Throws std::invalid_argument when a given value is not a positive number of that form.
body_match same_body(const scheme_table& t, const std::array<std::string_view, 3>& body);

/// In floating point: the ratios I1/I3 and I2/I3 agree to `relative` (1e-12: moments typed or
/// solved; LAMMPS's bodies, whose moments come from rounded coordinates, take a wider one).
/// Throws std::invalid_argument when a moment is not finite and positive.
body_match same_body(const scheme_table& t, const std::array<double, 3>& body, double relative = 1e-12);

}  // namespace rotlie::schemes
