#pragma once
// Turns a command-line scheme name into a scheme table: a reference scheme (RS4-S5-McLachlan:CBA),
// a dedicated solution SCHEME:PERM:LABEL solved for the body given (N2:BAC:2, P1:BAC:5), or the
// path of a scheme-table file. This is where the symbolic and numeric sides meet, through text.
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/small_matrix.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::app {

/// The range of every scale the numeric subcommands take (moments, |G0|, h, T, and the angular
/// rate |G0|/I): inside it no product or quotient of two of them leaves double precision.
inline constexpr int max_decimal_exponent = 150;

/// What to do with a scheme-table file solved for another body (its `inertia` line, compared up
/// to a common factor): refuse it and name --force (integrate, order), refuse it where the command
/// has no such option (md), or use it with a warning on stderr (--force given).
enum class foreign_table { refuse_unless_forced, refuse, use_with_warning };

/// Throws usage_error for an unknown name, a bad label or a file that fails its checks.
schemes::scheme_table lookup_scheme(const std::string& name, const lie::moments_of_inertia& body,
                                    foreign_table policy = foreign_table::refuse_unless_forced);

/// --perm of the solving subcommands: all (every permutation, bch order) or one name.
std::vector<std::string> permutations_option(const std::string& perm);

/// --inertia of the solving subcommands: required, exact, validated (eq. 77).
lie::moments_of_inertia required_moments_option(const std::string& text);

/// --inertia as exact moments (water, sphere, I1,I2,I3), validated (eq. 77): any size, for the
/// exact subcommands (remainder).
lie::moments_of_inertia parse_moments_option(const std::string& text);
/// The same, each moment within 1e-150 … 1e150, for the numeric subcommands.
lie::moments_of_inertia parse_inertia_option(const std::string& text);
models::vec3<double> to_double(const lie::moments_of_inertia& body);

/// A positive number within 1e-150 … 1e150 given as a decimal or a rational (1/64); `what` names the option.
double parse_positive(const std::string& text, const std::string& what);
/// g1,g2,g3 (decimals or rationals), not all zero, |G0| within 1e-150 … 1e150.
models::vec3<double> parse_momentum(const std::string& text);

/// The scales of one numeric run together: the fastest angular rate |G0|/I_min and the angle
/// |G0| T / I_min stay within the range above, so that no energy, rate or phase overflows.
void check_numeric_scales(const std::string& inertia, const std::string& g0, const std::string& total);

}  // namespace rotlie::app
