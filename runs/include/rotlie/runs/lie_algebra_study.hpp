#pragma once
// The computation behind the report's section "Lie algebra of the free rigid body": the dimensions of
// L_k with Theorems 1 and 2 checked at every order, and Table 1 from them. Plain results;
// reports/lie_algebra_section writes and formats them.
#include <vector>

#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/lie/stage_table.hpp"

namespace rotlie::runs {

/// Table 1 of the paper stops at order 10.
inline constexpr int lie_algebra_table_orders = 10;

struct lie_algebra_study_result {
  int max_order = 0;
  std::vector<lie::graded_piece> pieces;  ///< L_1 … L_max_order
  double seconds = 0;                     ///< wall time of the dimensions
  bool all_theorems = true;               ///< Theorems 1 and 2 hold at every order
  bool all_attained = true;               ///< the Theorem 1-2 bound is attained at every order
  std::vector<lie::stage_block> blocks;   ///< Table 1
};

/// Orders 1 … max_order.
lie_algebra_study_result lie_algebra_study(int max_order);

}  // namespace rotlie::runs
