#pragma once
// Whether closed quadrilaterals (5 points each, the first repeated) tile a region: each edge counted
// by the cells that use it (corners compared to 1e-9). Shared by the body-cell tests.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace rotlie::test_tiling {

using point = std::pair<double, double>;

struct tiling {
  std::size_t cells = 0, shared_edges = 0, outer_edges = 0, overused_edges = 0, open_cells = 0;
  double smallest_area = INFINITY;
};

inline tiling tiling_of(const std::vector<std::vector<point>>& series) {
  tiling t;
  std::map<std::pair<std::pair<long, long>, std::pair<long, long>>, int> uses;
  const auto key = [](const point& p) { return std::make_pair(std::lround(p.first * 1e9), std::lround(p.second * 1e9)); };
  for (const auto& points : series)
    for (std::size_t k = 0; k + 5 <= points.size(); k += 5) {
      ++t.cells;
      if (key(points[k]) != key(points[k + 4])) ++t.open_cells;
      double area = 0;
      for (std::size_t i = k; i < k + 4; ++i) {
        area += points[i].first * points[i + 1].second - points[i + 1].first * points[i].second;
        auto a = key(points[i]), b = key(points[i + 1]);
        if (a == b) continue;  // a corner of a triangle-shaped cell at the boundary
        if (b < a) std::swap(a, b);
        ++uses[{a, b}];
      }
      t.smallest_area = std::min(t.smallest_area, std::abs(area) / 2);
    }
  for (const auto& [edge, n] : uses) (n == 1 ? t.outer_edges : n == 2 ? t.shared_edges : t.overused_edges) += 1;
  return t;
}

}  // namespace rotlie::test_tiling
