#pragma once
// Turns a command-line scheme name into a scheme table: a reference scheme (RS4-S5-McLachlan:CBA),
// a dedicated solution SCHEME:PERM:LABEL solved for the body given (N2:BAC:2, P1:BAC:5), or the
// path of a scheme-table file. This is where the symbolic and numeric sides meet, through text.
#include <string>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/small_matrix.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::app {

/// Throws usage_error for an unknown name, a bad label or a file that fails its checks.
schemes::scheme_table lookup_scheme(const std::string& name, const lie::moments_of_inertia& body);

/// --inertia as exact moments (water, sphere, I1,I2,I3), validated (eq. 77).
lie::moments_of_inertia parse_inertia_option(const std::string& text);
models::vec3<double> to_double(const lie::moments_of_inertia& body);

/// A positive finite number given as a decimal or a rational (1/64); `what` names the option.
double parse_positive(const std::string& text, const std::string& what);
/// g1,g2,g3 (decimals or rationals), finite and not all zero.
models::vec3<double> parse_momentum(const std::string& text);

}  // namespace rotlie::app
