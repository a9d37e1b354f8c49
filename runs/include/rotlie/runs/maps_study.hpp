#pragma once
// The computations behind the report's sections "Maps" and "Do the maps tell the truth?": a family's map
// computed as `rotlie map` computes it by default, the fast maps checked against the exact solver, the
// measured ratios on a grid of bodies; each timed. Plain results; the sections draw and format them.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/runs/map_check.hpp"
#include "rotlie/solver/body_grid.hpp"

namespace rotlie::runs {

/// Receives one line of progress.
using study_progress = std::function<void(const std::string&)>;

/// A map file's worth: its path name (exact, fast, screened), the file's text (header line, then one
/// line per body in grid order) and the wall time of the computation.
struct computed_map {
  std::string method;
  std::string file_text;
  std::vector<std::string> lines;  ///< the body lines
  double seconds = 0;
};

/// The family's map at grid K by the path `rotlie map` takes by default (N continued, P screened at
/// K ≥ 200 and exact below, R exact), with the neighbour check of a screened map.
computed_map compute_family_map(const std::string& family, int K, const study_progress& progress = {});

/// check_map_lines with its wall time.
std::pair<map_check_result, double> timed_map_check(const std::string& family, int K, std::vector<nlohmann::json> bodies,
                                                    std::size_t count, std::uint64_t seed,
                                                    const std::function<void(int done, int of)>& progress = {});

/// The measured ratios (maps_truth_csv) of truth_bodies(K), and the CPU time they took.
struct truth_measurements {
  std::string csv;
  std::size_t bodies = 0;
  double cpu_seconds = 0;
};
truth_measurements measure_truth_grid(int K, const study_progress& progress = {});

/// Rotations per step of a mapped family's schemes (9 for N, 10 for R, 11 for P).
int mapped_family_cost(const std::string& family);

/// The moments (I1, I2) of the body (i, j) of the grid of K, in double.
std::pair<double, double> grid_moments(int K, int i, int j);

}  // namespace rotlie::runs
