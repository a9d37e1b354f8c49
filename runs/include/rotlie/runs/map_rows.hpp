#pragma once
// The one map-row driver: the lines of a row of the grid of bodies (s fixed), by the path a family's
// map takes, for `rotlie map` (on any number of processes) and the report's maps section alike.
#include <string>
#include <utility>
#include <vector>

#include "rotlie/bch/families.hpp"
#include "rotlie/solver/body_grid.hpp"

namespace rotlie::runs {

/// The exact solver's line of one body (a failure line when the solve fails).
std::string exact_map_line(const solver::grid_body& g, const std::string& family);

/// The lines (JSON text, runs/map_file.hpp) of the bodies [first, first + count) of `bodies` that
/// are still to do (done[k] == 0), each with its index in `bodies`. The fast and screened paths
/// carry solutions along the whole row whatever is done, so that every line is the same in any
/// run; if the row fails as a whole, each body is solved on its own and a failure stays on its line.
std::vector<std::pair<std::size_t, std::string>> map_row_lines(const std::vector<solver::grid_body>& bodies,
                                                               std::size_t first, std::size_t count,
                                                               const std::vector<char>& done, const std::string& family,
                                                               bch::map_method method);

}  // namespace rotlie::runs
