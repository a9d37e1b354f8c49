#pragma once
// The fixed grid over the set of rigid bodies of LV section 5.1 (after Fassò 2003): bodies
// (I1, I2, 1) in the triangle I1 ≤ I2 ≤ 1, I1 + I2 ≥ 1, sampled at s, t ∈ {0, 1/K, …, 1} by
//   I2 = 1/2 + s/2,   I1 = (1 − I2) + t·(2 I2 − 1),
// exact rationals, so that every run on every machine computes the same bodies. K = 200 gives the
// paper's 40,401 points. t = 0 is the flat edge I1 + I2 = 1, s = 1 the edge I2 = I3, t = 1 the edge
// I1 = I2 and s = 0 the flat symmetric top (1/2, 1/2, 1) for every t.
#include <cln/rational.h>

#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::solver {

/// Grids finer than this would take years per map at today's cost per body.
inline constexpr long max_grid_divisions = 2000;

struct grid_body {
  int i = 0, j = 0;   ///< s = i/K, t = j/K
  cln::cl_RA s, t;
  lie::moments_of_inertia body;  ///< (I1, I2, 1)
  bool symmetric = false;        ///< two equal moments: skipped by the maps, as in the paper
  bool flat = false;             ///< I1 + I2 = I3 (t = 0): kept
};

/// The body at grid indices (i, j), 0 ≤ i, j ≤ K. Throws std::invalid_argument outside.
grid_body grid_point(int K, int i, int j);

/// Every grid point, (K + 1)² of them, in the fixed order i (s) ascending, then j (t) ascending.
/// Throws std::invalid_argument for K < 1 or K > max_grid_divisions.
std::vector<grid_body> body_grid(int K);

/// The points a map computes: body_grid(K) without the symmetric tops, same order.
std::vector<grid_body> asymmetric_grid(int K);

/// Where a body (I1, I2, I3) in any unit lies in the triangle: (s, t) of its scaled, sorted moments
/// I1 ≤ I2 ≤ I3 = 1, exactly. Throws std::invalid_argument for a symmetric top (I2 = 1/2 leaves t
/// undefined only there) or an unphysical body.
std::pair<cln::cl_RA, cln::cl_RA> triangle_coordinates(const lie::moments_of_inertia& body);

}  // namespace rotlie::solver
