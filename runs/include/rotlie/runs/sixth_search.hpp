#pragma once
// The search behind `rotlie sixth`: dedicated 6th-order schemes for one body. Palindromic words of
// 21 stages (ABC) or 19 (RS) in every permutation, scanned by Newton from random starts (resumable
// from a state file), the roots ranked by ‖H_R7‖, the best polished and written as order-6 tables.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/solver/sixth_order_scan.hpp"

namespace rotlie::runs {

/// The systems named by --words (WORD or WORD:PERM items, comma-separated), or every palindrome of
/// the splitting's length (all); a sphere needs the permutation ABC only. Throws bad_input.
std::vector<solver::scanned_system> sixth_order_systems(const std::string& words, bool all, bch::splitting split,
                                                        bool sphere);

struct sixth_search_request {
  lie::moments_of_inertia body;
  bch::splitting split = bch::splitting::abc;
  std::vector<solver::scanned_system> systems;
  int starts = 40;  ///< Newton starts per system (the scan's budget)
  int best = 5;     ///< roots to polish and write
  int digits = 45;
  std::filesystem::path out;  ///< empty: no state and no tables written
};

/// One of the best roots: polished into a table, or why not.
struct sixth_order_table {
  bool polished = false;
  std::string name, word, permutation, file, why;
  double remainder7 = 0, remainder7_at_equal_cost = 0, max_coefficient = 0, residual = 0, jacobian_ratio = 0;
  double smallest_free_coefficient = 0;
  int cost = 0, hits = 0;
};

struct sixth_search_result {
  solver::hit_statistics stats;
  std::vector<sixth_order_table> best;  ///< by ‖H_R7‖, polished or not, until `best` are polished
  double cpu_seconds = 0;
};

/// Runs the scan (continuing the state in `out` where it exists), ranks and polishes. Throws
/// bad_input for a state file that cannot be read.
sixth_search_result sixth_search(const sixth_search_request& request,
                                 const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
