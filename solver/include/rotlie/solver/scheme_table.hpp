#pragma once
// Writing a solution as a scheme table: the only thing that crosses from the symbolic side
// to the numeric side (docs/scheme_table_format.md). Plain text, one stage per line, every
// coefficient as a decimal string of at least 40 significant digits, with provenance.
#include <string>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::solver {

/// The table's name, e.g. "N2:BAC:2" (the CLI's SCHEME:PERM:LABEL form).
std::string scheme_table_name(const dedicated_solution& s);

/// The table text; digits is the number of significant digits printed (≥ 40 is the contract).
std::string scheme_table_text(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits);

}  // namespace rotlie::solver
