#pragma once
// LV section 4 computed (the rendering is reports/accuracy_section.cpp): the protocol curves of
// Figs. 1-5 for the spherical top and water, and the paper's seven accuracy claims as ratios of them.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

/// One of the paper's claims: `better` is `paper` times more accurate than `worse` (LV section 4).
struct accuracy_claim {
  std::string text;  ///< the claim as the paper makes it
  double paper = 0;  ///< the paper's ratio
  scheme_curve worse, better;
  /// Ours at equal reduced step h/C, the paper's measure.
  double at_equal_reduced_step() const { return ratio_at_equal_reduced_step(worse, better); }
  /// Ours at equal measured CPU time (double stepper).
  double at_equal_cpu_time() const { return ratio_at_equal_cpu_time(worse, better); }
};

struct accuracy_curves {
  int max_level = 0;  ///< h = 2^-1 … 2^-max_level
  /// Spherical top: the N solutions of Table 2 (sorted by name), then ABCBA2 and ABCBA4 Yoshida.
  std::vector<scheme_curve> sphere;
  std::vector<solver::dedicated_solution> sphere_solutions;  ///< sorted by name, as `sphere`
  /// Water: Table 4's N selection, then leapfrog and Yoshida at their best permutations (Fig. 3).
  std::vector<scheme_curve> fig3;
  /// Water: every reference scheme at its best permutation.
  std::vector<scheme_curve> references;
  /// Water: N2 BAC (2), P1 BAC (5), R ABC (4), RS4 S5 McLachlan CBA (Fig. 5).
  std::vector<scheme_curve> fig5;
  std::vector<accuracy_claim> claims;  ///< the paper's seven claims, in the paper's order
};

/// Runs the protocol (protocol_runner) for every curve of the section and forms the claims;
/// `progress` gets one line per stage and may be empty.
accuracy_curves compute_accuracy_curves(int max_level, const std::function<void(std::string_view)>& progress = {});

/// The curve of that name; throws std::logic_error when absent.
const scheme_curve& curve_named(const std::vector<scheme_curve>& curves, const std::string& name);
/// The curve of a reference scheme (base name) at whichever permutation it was run; throws
/// std::logic_error when absent.
const scheme_curve& best_permutation_of(const std::vector<scheme_curve>& curves, const std::string& base);

}  // namespace rotlie::runs
