// The computation behind the report's section "Lie algebra of the free rigid body" (see lie_algebra_study.hpp).
#include "rotlie/runs/lie_algebra_study.hpp"

#include <chrono>

namespace rotlie::runs {

lie_algebra_study_result lie_algebra_study(int max_order) {
  lie_algebra_study_result out;
  out.max_order = max_order;
  const auto start = std::chrono::steady_clock::now();
  out.pieces = lie::lie_poisson_algebra(max_order);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<std::size_t> dims;
  for (const auto& p : out.pieces) {
    dims.push_back(p.dimension);
    out.all_theorems = out.all_theorems && p.theorem1 && p.theorem2.value_or(true);
    out.all_attained = out.all_attained && p.bound_attained();
  }
  out.blocks = lie::stage_table(lie_algebra_table_orders, dims);
  return out;
}

}  // namespace rotlie::runs
