#pragma once
// The reference schemes of the literature as scheme tables (REFERENCE.md §1, LV section 4):
// leapfrog, Yoshida SS3, Suzuki SS5, McLachlan SS5 (compositions of ABCBA or RSR), and McLachlan's
// type-S S4 and S5 (RS directly; ABC through the adjoint-composition construction).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::schemes {

/// All base names: ABCBA2, RSR2, ABCBA4-SS3-Yoshida, …, RS4-S5-McLachlan.
const std::vector<std::string>& reference_scheme_names();

/// A reference scheme by name, optionally with a permutation suffix (RS4-S5-McLachlan:CBA);
/// nullopt for an unknown name. Throws std::invalid_argument for an unknown permutation.
std::optional<scheme_table> reference_scheme(std::string_view name);

/// Substitutes the letters of an ABC table (A → perm[0], B → perm[1], C → perm[2]); for an RS
/// table records which axes play R and S. Throws std::invalid_argument for an unknown permutation.
scheme_table permuted(scheme_table t, const std::string& permutation);

}  // namespace rotlie::schemes
