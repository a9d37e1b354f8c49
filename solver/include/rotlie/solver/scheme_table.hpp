#pragma once
// Writing a solution as a scheme table: the only thing that crosses from the symbolic side
// to the numeric side (docs/scheme_table_format.md). Plain text, one stage per line, every
// coefficient as a decimal string of at least 40 significant digits, with provenance. The
// `order` line states what the written decimals certify (table_certificate.hpp), never more.
#include <map>
#include <string>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/table_certificate.hpp"

namespace rotlie::solver {

/// The table's name, e.g. "N2:BAC:2" (the CLI's SCHEME:PERM:LABEL form).
std::string scheme_table_name(const dedicated_solution& s);

/// The stage values exactly as a table of `digits` significant digits writes them.
std::map<std::string, cln::cl_RA> written_coefficients(const dedicated_solution& s, int digits);

/// The table text; digits is the number of significant digits printed (≥ 40 is the contract). Its
/// `order` and `residual` lines are the certificate of the printed decimals; body is the body as
/// given (any unit), written on the `inertia` line.
std::string scheme_table_text(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits);

/// What a searched (not eliminated) solution's table states beside its stages.
struct searched_table_lines {
  std::string name;
  int order = 4;
  int digits = 45;
  cln::cl_RA residual;            ///< the certificate of the written decimals, relative to the terms
  std::string comment;            ///< one line before analytic_remainder (without the '#')
  std::string analytic_remainder;  ///< as written
  std::string source;
};

/// The table text of a symmetric word's solution found by a numerical search: the layout's stages
/// with `values` (every stage coefficient) written to `lines.digits` significant digits.
std::string searched_table_text(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                                const std::map<std::string, cln::cl_RA>& values, const searched_table_lines& lines);

/// A numeric table's split as the symbolic side names it (the two enums meet only here, where both
/// libraries are visible). Throws std::invalid_argument for TV: free flight and kick are no
/// splitting of the free rigid body's Hamiltonian.
bch::splitting splitting_of(schemes::split split);

/// The solution as the numeric side sees it: its table text (40 digits by default), parsed.
schemes::scheme_table scheme_table_of(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits = 40);

}  // namespace rotlie::solver
