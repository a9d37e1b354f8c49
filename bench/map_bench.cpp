// Seconds per body of the body-set maps (LV section 5), exact solver against the continued rows of
// the default path, in CPU time of this process, with the number of bodies the continued path still
// hands to the exact solver. Not Google Benchmark: one timed pass over chosen rows of the grid.
//   map_bench FAMILY K ROWS...   (rows are the grid index i of s = i/K, 1 ≤ i ≤ K − 1)
//   map_bench FAMILY K ROWS... --exact-every M   (also times the exact solver at every M-th body)
//   map_bench FAMILY K ROWS... --out FILE        (also writes those rows as a map file, for map_check)
//   map_bench FAMILY K ROWS... --screened [--per-permutation]   (the screened path, screened_map.hpp)
#include <ctime>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "rotlie/runs/map_file.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/family_systems.hpp"
#include "rotlie/solver/screened_map.hpp"

namespace {
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }
}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: map_bench FAMILY K ROW... [--exact-every M]\n";
    return 2;
  }
  const std::string family = argv[1];
  const int K = std::stoi(argv[2]);
  std::vector<int> rows;
  int exact_every = 0;
  std::string out_file;
  bool screened = false, per_permutation = false;
  for (int a = 3; a < argc; ++a) {
    if (std::string(argv[a]) == "--exact-every" && a + 1 < argc) exact_every = std::stoi(argv[++a]);
    else if (std::string(argv[a]) == "--out" && a + 1 < argc) out_file = argv[++a];
    else if (std::string(argv[a]) == "--screened") screened = true;
    else if (std::string(argv[a]) == "--per-permutation") per_permutation = true;
    else rows.push_back(std::stoi(argv[a]));
  }
  double t = cpu_seconds();
  rotlie::solver::family_systems(family);
  const double setup = cpu_seconds() - t;
  std::cout << "family " << family << ": systems interpolated in " << setup << " s CPU (once per process)\n" << std::flush;
  std::ofstream out;
  if (!out_file.empty()) {
    out.open(out_file);
    out << rotlie::runs::map_header(family, K, rows.size() * static_cast<std::size_t>(K), screened ? "screened" : "fast").dump() << "\n";
  }
  rotlie::solver::continuation_counts counts;
  double fast = 0, exact = 0;
  int bodies = 0, exact_bodies = 0;
  for (const int i : rows) {
    std::vector<rotlie::solver::grid_body> row;
    for (int j = 0; j < K; ++j) row.push_back(rotlie::solver::grid_point(K, i, j));
    t = cpu_seconds();
    rotlie::solver::continuation_counts c;
    rotlie::solver::screening_counts sc;
    const auto points = screened ? rotlie::solver::screened_map_points(row, family, per_permutation, &sc)
                                 : rotlie::solver::continued_map_points(row, family, &c);
    if (screened) c.system_solves = sc.system_solves;
    if (out)
      for (std::size_t k = 0; k < row.size(); ++k) out << rotlie::runs::map_line(row[k], points[k]).dump() << "\n" << std::flush;
    const double dt = cpu_seconds() - t;
    fast += dt;
    bodies += static_cast<int>(row.size());
    counts.exact += c.exact;
    counts.continued += c.continued;
    counts.system_solves += c.system_solves;
    std::cout << "row i = " << i << ": " << row.size() << " bodies in " << dt << " s CPU, " << c.exact
              << " wholly by the exact solver, " << c.system_solves << " exact system solves of "
              << row.size() * rotlie::solver::family_systems(family).size();
    if (screened)
      std::cout << " (" << sc.confirmations << " bests completed, " << sc.counts << " by a count of real eliminant roots), "
                << sc.dropped << " solutions dropped by chains, " << sc.checkpoints << " systems completed at checkpoints";
    std::cout << "\n" << std::flush;
    if (exact_every > 0)
      for (std::size_t j = 0; j < row.size(); j += static_cast<std::size_t>(exact_every)) {
        t = cpu_seconds();
        rotlie::solver::compute_map_point(row[j].body, family, rotlie::solver::map_digits);
        exact += cpu_seconds() - t;
        ++exact_bodies;
      }
  }
  const double asymmetric = static_cast<double>(K - 1) * K;
  std::cout << "continued rows: " << fast / bodies << " s CPU per body (" << counts.exact << " of " << bodies
            << " bodies exact); the full map at this K: " << (setup + fast / bodies * asymmetric) / 3600 << " core-hours\n";
  if (exact_bodies > 0)
    std::cout << "exact solver: " << exact / exact_bodies << " s CPU per body over " << exact_bodies
              << " bodies; the full map: " << exact / exact_bodies * asymmetric / 3600 << " core-hours\n";
}
