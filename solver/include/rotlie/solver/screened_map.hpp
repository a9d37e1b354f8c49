#pragma once
// The screened fast path of the maps for P, where the complete continuation of continued_map.hpp
// is too costly: a pair of real solutions is born and dies again between most exact bodies of a
// row, and each such event costs exact solves. The maps need the best integrator, not every
// solution.
//
// Along one row: every system is solved exactly at both ends; its real solutions are carried
// forward from the first body and backward from the last (continuation.hpp), a solution that
// cannot be carried (a fold, a step Newton refuses) is dropped from that chain, and at each body
// the two chains are merged. A minimum born and dying again between the ends is in neither chain
// (on a branch of the curve of order-4 solutions it is born above a minimum the chain holds, but
// it may sink below every other later): every 20 bodies, each system within a factor 2 of the
// body's best is made complete there, and the solutions the chains lacked are carried both ways
// until they stop (so back to where such a minimum was born).
// Then at each body the system holding the smallest ‖H_R5‖, and every system within 1e-9 of it,
// is made complete, again until the best is: the best integrator, its label and remainder always
// come from a complete solution set. A state is complete when the exact solver gave it, or when a
// complete state carries over whole with the same count of real eliminant roots (a birth or death
// changes the count by two; a death alone also stops the carry), at about half a solve. With
// `per_permutation`, the best of each permutation is completed the same way. What stays unproved
// is the screening itself: a minimum missed by every chain and checkpoint of a row leaves a best
// that is not. `rotlie map` therefore runs the neighbour check over the whole map once every row is
// done (runs/map_neighbour_check.hpp: each body against its neighbours' best systems, solved there
// exactly), and the maps check the result against the exact solver at random bodies (map_check).
#include <string>
#include <vector>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::solver {

struct screening_counts {
  int system_solves = 0;  ///< (system, body) pairs the exact solver solved: row ends and confirmations
  int confirmations = 0;  ///< of which confirmations of a best
  int dropped = 0;        ///< solutions a chain could not carry
  int counts = 0;         ///< real eliminant roots counted to carry a best's complete state instead of solving
  int checkpoints = 0;    ///< competitive systems made complete at the checkpoints
};

/// The map points of consecutive bodies of one grid row, in order. Throws what the exact solver throws.
std::vector<map_point> screened_map_points(const std::vector<grid_body>& row, const std::string& family,
                                           bool per_permutation = false, screening_counts* counts = nullptr);

}  // namespace rotlie::solver
