#pragma once
// A family as a user names it (--family N), for the command that will use it; the descriptors
// themselves are bch/families.hpp.
#include <string>
#include <vector>

#include "rotlie/bch/families.hpp"
#include "rotlie/solver/two_parameter.hpp"

namespace rotlie::runs {

/// Any family `rotlie solve` takes (N, R, P, Q, QRS). Throws bad_input.
const bch::family& family_to_solve(const std::string& name);

/// A family with a map over all bodies (N, R, P). Throws bad_input.
const bch::family& family_to_map(const std::string& name);

/// --scheme of `rotlie solve` within a family of named members: every member when `scheme` is
/// empty, else that one member. Throws bad_input for a scheme outside the family.
std::vector<std::string> members_asked(const bch::family& f, const std::string& scheme);

/// The family of two free parameters in a splitting (Q for ABC, QRS for RS).
const bch::family& two_parameter_family(bch::splitting split);

/// A searched system of two free parameters as FAMILY:WORD:PERM (Q:ABACBABABCABA:ABC).
std::string two_parameter_name(const solver::two_parameter_entry& e);

/// Its cost C/C0 (its family's).
int two_parameter_cost(const solver::two_parameter_entry& e);

/// The path a map of the family at grid K takes: its fast path unless `exact`, the family has none,
/// or K is coarser than the grids where the fast path was checked (family::fast_from_grid).
/// Throws bad_input for `fast` where the fast path is not checked against the exact solver.
bch::map_method map_method_asked(const bch::family& f, int K, bool exact, bool fast);

/// The name of a map path as the header of a map file says it: "exact", "fast", "screened".
std::string map_method_name(bch::map_method m);

}  // namespace rotlie::runs
