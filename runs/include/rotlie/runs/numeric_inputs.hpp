#pragma once
// The numbers of a numeric run as a user types them (a step, a time span, an initial angular
// momentum), checked so that no energy, rate or phase of the run overflows double.
#include <string>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

/// A positive number within 1e-150 … 1e150 given as a decimal or a rational (1/64); `what` names
/// the option. Throws bad_input.
double positive_number(const std::string& text, const std::string& what);

/// A comma-separated list of such numbers ("2000" or "2000,2500"), each checked as positive_number.
std::vector<double> positive_numbers(const std::string& text, const std::string& what);

/// A finite number of either sign (zero too), its magnitude at most 1e150; `what` names it.
double real_number(const std::string& text, const std::string& what);

/// A comma-separated list of such numbers.
std::vector<double> real_numbers(const std::string& text, const std::string& what);

/// g1,g2,g3 (decimals or rationals), not all zero, |G0| within 1e-150 … 1e150. Throws bad_input.
models::vec3<double> initial_momentum(const std::string& text);

/// The scales of one numeric run together: the fastest angular rate |G0|/I_min and the angle
/// |G0| T / I_min stay within the range above. Throws bad_input.
void check_numeric_scales(const std::string& inertia, const std::string& g0, const std::string& total);

/// The largest T/h a run takes (about an hour of SIER2 in double on the spin-orbit scene).
inline constexpr double max_steps = 2e9;

/// T/h as a whole number of steps (exactly for exact decimals or rationals, or within 1e-9 relative
/// for decimals typed from a float), or bad_input naming --T and --h with the two nearest runs that are.
long whole_steps(const std::string& h_text, const std::string& T_text, double h, double T);

}  // namespace rotlie::runs
