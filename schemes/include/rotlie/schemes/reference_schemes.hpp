#pragma once
// The reference schemes of the literature as scheme tables (REFERENCE.md §1, LV section 4):
// leapfrog, Yoshida SS3, Suzuki SS5, McLachlan SS5 (compositions of ABCBA or RSR), and McLachlan's
// type-S S4 and S5 (RS directly; ABC through the adjoint-composition construction); and the two
// splittings of a body under torques into free flight T and kick V (van Zon & Schofield eqs. 7–8).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::schemes {

/// The free-rotation base names (ABC and RS tables): ABCBA2, RSR2, ABCBA4-SS3-Yoshida, …, RS4-S5-McLachlan.
const std::vector<std::string>& reference_scheme_names();

/// The general 6th-order compositions (symmetric compositions of ABCBA / RSR: Yoshida's triple jump of
/// triple jumps and solution A, Kahan & Li's s9odr6a; Blanes & Moan's S10 for RS, and for ABC through
/// the adjoint composition): ABCBA6-SS9-Yoshida, …, RS6-S10-BlanesMoan. Kept apart from the 4th-order
/// list so that the LV figures stay the paper's selection.
const std::vector<std::string>& reference_sixth_order_scheme_names();

/// The TV base names (free flight T, kick V): Strang-TV, PEFRL-TV.
const std::vector<std::string>& reference_tv_scheme_names();

/// A reference scheme by name (any list), optionally with a permutation suffix
/// (RS4-S5-McLachlan:CBA); nullopt for an unknown name. Throws std::invalid_argument for an
/// unknown permutation, and for any permutation of a TV table.
std::optional<scheme_table> reference_scheme(std::string_view name);

/// Substitutes the letters of an ABC table (A → perm[0], B → perm[1], C → perm[2]); for an RS
/// table records which axes play R and S. Throws std::invalid_argument for an unknown permutation
/// and for a TV table, whose letters name no body axes.
scheme_table permuted(scheme_table t, const std::string& permutation);

}  // namespace rotlie::schemes
