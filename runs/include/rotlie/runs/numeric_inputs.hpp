#pragma once
// The numbers of a numeric run as a user types them (a step, a time span, an initial angular
// momentum), checked so that no energy, rate or phase of the run overflows double.
#include <string>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

/// A positive number within 1e-150 … 1e150 given as a decimal or a rational (1/64); `what` names
/// the option. Throws bad_input.
double positive_number(const std::string& text, const std::string& what);

/// g1,g2,g3 (decimals or rationals), not all zero, |G0| within 1e-150 … 1e150. Throws bad_input.
models::vec3<double> initial_momentum(const std::string& text);

/// The scales of one numeric run together: the fastest angular rate |G0|/I_min and the angle
/// |G0| T / I_min stay within the range above. Throws bad_input.
void check_numeric_scales(const std::string& inertia, const std::string& g0, const std::string& total);

}  // namespace rotlie::runs
