#pragma once
// The fast path of the maps: along one row of the grid (fixed s, t ascending) the real solutions
// of each system (scheme, permutation) at a body start Newton at the next body (continuation.hpp),
// on the systems the exact solver sets up (family_systems.hpp), system by system. The exact solver
// runs on the system at both ends of the row. A chain that stops (Newton refuses: a solution born,
// dying or running off) is confirmed by the exact solver at its last body and restarted from the
// exact solution where it stopped; a chain whose solutions differ at its exact end from the exact
// ones (a solution born on the way) is cut in two at an exact body and each half checked the same
// way, down to neighbours. A system is never continued from a body where it is singular. So every solution comes from the exact solver or from a chain
// whose two ends the exact solver confirms.
#include <string>
#include <vector>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::solver {

struct continuation_counts {
  int exact = 0;          ///< bodies where every system came from the exact solver
  int continued = 0;      ///< bodies with at least one system carried along a confirmed chain
  int system_solves = 0;  ///< (system, body) pairs the exact solver solved
};

/// The map points of consecutive bodies of one grid row, in order. Throws what the exact solver throws.
std::vector<map_point> continued_map_points(const std::vector<grid_body>& row, const std::string& family,
                                            continuation_counts* counts = nullptr);

/// The digits of the exact solver in the maps (as `solve`'s default).
inline constexpr int map_digits = 40;

}  // namespace rotlie::solver
