#pragma once
// One point of the maps of LV section 5 (Figs. 7–10): for a body, the best integrator of a
// dedicated family at each of the six permutations by analytic remainder ‖H_R5‖ (eq. 64, as in
// Table 4), the best permutation of the reference RS4 S5 McLachlan by the same measure, and the
// ratio R_M / R_best × (C_M / C)^4 that puts both at equal cost (section 5.2: (12/9)^4 for N).
#include <optional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::solver {

/// The reference scheme of section 5.1 (the best reference for water, section 4.3).
inline constexpr const char* map_reference_scheme = "RS4-S5-McLachlan";

/// N1…N7, R, or P1…P15 for "N", "R", "P"; throws std::invalid_argument otherwise.
std::vector<std::string> family_schemes(const std::string& family);

/// Rotations about principal axes per step (section 4.1): 9 for N, 10 for R, 11 for P, from the words.
int family_cost(const std::string& family);

/// ‖H_R5‖ (eq. 64, body scaled to I3 = 1) of a reference scheme (schemes::reference_scheme_names) at a
/// permutation, from its stage values. Throws std::invalid_argument for an unknown name.
double reference_analytic_remainder(const lie::moments_of_inertia& body, const std::string& name,
                                    const std::string& permutation);
/// Its cost in rotations per step (12 for RS4 S5 McLachlan).
int reference_cost(const std::string& name);

struct permutation_best {
  std::string permutation;
  std::optional<dedicated_solution> best;  ///< absent when no system of the family has a solution here
  /// Its system was solved by the exact solver at this body (always, but on the screened path):
  /// else its label counts only the solutions continuation carried there.
  bool confirmed = true;
};

struct singular_system {
  std::string scheme, permutation, note;
};

struct map_point {
  std::string family;
  std::vector<permutation_best> per_permutation;  ///< ABC, BCA, CAB, ACB, CBA, BAC
  std::optional<dedicated_solution> best;         ///< smallest ‖H_R5‖ over all permutations
  std::vector<double> reference_remainders;       ///< RS4 S5 McLachlan, same permutation order
  std::string reference_permutation;              ///< where it is smallest
  double reference_remainder = 0;
  std::optional<double> ratio;                    ///< R_M / R_best × (C_M / C)^4; absent without a best
  std::vector<singular_system> singular;          ///< systems without isolated solutions at this body
  int real_solutions = 0;                         ///< over all systems
  bool complete = true;  ///< every real solution of every system known (real_solutions counts them); not on the screened path
};

/// Builds the map point from a solved family (solve_dedicated over every permutation of the family).
map_point summarize_family(const lie::moments_of_inertia& body, const std::string& family, const family_result& solved);

/// Solves the family at the body (the exact solver, `digits` digits as `solve`) and summarizes it.
map_point compute_map_point(const lie::moments_of_inertia& body, const std::string& family, int digits = 40);

}  // namespace rotlie::solver
