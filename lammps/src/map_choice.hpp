// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// `rotor auto` for a body shape from the maps shipped with rotlie (data/maps-K200, LV section 5 at
// the paper's grid): the three families' lines at the grid body nearest the shape name the family,
// scheme and permutation that beat the reference there, if any; that one system is then solved for
// the shape itself (a fraction of a second, where solving every family at every permutation as
// `rotlie best` does takes about 45 s), and its best real solution runs the shape when it still
// beats the reference at the shape's own moments. Otherwise the reference RS4-S5-McLachlan at the
// shape's best permutation runs it.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::lammps {

/// The grid of the shipped maps (--grid 200).
inline constexpr int shipped_grid = 200;

/// The grid indices (i, j) nearest a body (moments increasing), kept off the symmetric edges, which
/// the maps leave out.
std::pair<int, int> nearest_grid_point(const std::array<double, 3>& moments);

/// The lines of the shipped N, R and P maps at grid points, read in one pass over each map.
class shipped_map_lines {
 public:
  /// Reads the maps' lines at `points`. Throws std::runtime_error naming the missing or unreadable map.
  explicit shipped_map_lines(const std::vector<std::pair<int, int>>& points);
  /// The N, R, P lines at a point read (a family's line may be missing: a failed body of its map).
  std::vector<std::string> at(std::pair<int, int> point) const;

 private:
  std::map<std::pair<int, int>, std::vector<std::string>> lines_;
};

/// Whether the shipped maps are where rotlie looks for them (runs::shipped_map).
bool shipped_maps_present();

/// The table `rotor auto` runs for the exact shape `body`, from the maps' lines at its grid point.
/// A dedicated system without a real solution for the body is no error: the reference runs it then.
schemes::scheme_table table_from_maps(const lie::moments_of_inertia& body, const std::vector<std::string>& lines);

}  // namespace rotlie::lammps
