// The report's body-set maps through the binary: drawn as continuous maps over the triangle, each body
// a closed cell and the cells tiling the region between them, not rows of separate squares with white
// gaps (Fig. 8 at --grid 40 once was). Read from the CSV written beside each chart (the numbers gnuplot
// drew). About a minute: the maps section also checks 4 bodies of the shipped P map exactly.
#include <boost/test/unit_test.hpp>

#include "../apps/cli_support.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(map_chart_cli_test)

namespace fs = std::filesystem;
using namespace rotlie::test_cli;

namespace {

using point = std::pair<double, double>;

// series → its points, from a chart CSV (series,x,y[,z]; the series quoted)
std::map<std::string, std::vector<point>> chart_points(const fs::path& csv) {
  std::map<std::string, std::vector<point>> out;
  std::istringstream text(slurp(csv));
  std::string line;
  std::getline(text, line);  // header
  while (std::getline(text, line)) {
    const auto close = line.find("\",");
    BOOST_REQUIRE(line.front() == '"' && close != std::string::npos);
    std::istringstream numbers(line.substr(close + 2));
    double x = 0, y = 0;
    char comma = 0;
    numbers >> x >> comma >> y;
    out[line.substr(1, close - 1)].push_back({x, y});
  }
  return out;
}

struct tiling {
  std::size_t cells = 0, shared_edges = 0, outer_edges = 0, overused_edges = 0;
  double smallest_area = INFINITY;
};

// The series' points read as closed quadrilaterals (5 points, the first repeated); each edge counted by
// the cells that use it (corners compared to 1e-9).
tiling tiling_of(const std::vector<std::vector<point>>& series) {
  tiling t;
  std::map<std::pair<std::pair<long, long>, std::pair<long, long>>, int> uses;
  const auto key = [](const point& p) { return std::make_pair(std::lround(p.first * 1e9), std::lround(p.second * 1e9)); };
  for (const auto& points : series) {
    BOOST_TEST_REQUIRE(points.size() % 5 == 0u);
    for (std::size_t k = 0; k < points.size(); k += 5) {
      ++t.cells;
      BOOST_TEST((key(points[k]) == key(points[k + 4])));  // closed
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
  }
  for (const auto& [edge, n] : uses) (n == 1 ? t.outer_edges : n == 2 ? t.shared_edges : t.overused_edges) += 1;
  return t;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_maps_are_cells_that_tile_the_triangle) {
  constexpr int K = 12;
  const fs::path maps = scratch() / "maps", report = scratch() / "report";
  const auto map = run("map --family N --grid " + std::to_string(K) + " --out " + maps.string());
  BOOST_TEST_REQUIRE(map.status == 0, map.err);
  const auto r = run("report --sections maps --maps " + maps.string() + " --out " + report.string());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const std::size_t bodies = 132;  // the asymmetric bodies of the map at --grid 12 (its summary's count)
  for (const char* chart : {"maps_fig8_ratio_N.csv", "maps_fig7a_best_N.csv", "maps_fig7b_permutation_N.csv"}) {
    BOOST_TEST_CONTEXT(chart) {
      std::vector<std::vector<point>> cells;
      for (auto& [name, points] : chart_points(report / chart))
        if (name.find("ratio = 1") == std::string::npos) cells.push_back(points);  // the contour's segments aside
      const auto t = tiling_of(cells);
      BOOST_TEST(t.cells == bodies);
      BOOST_TEST(t.smallest_area > 0);
      BOOST_TEST(t.overused_edges == 0u);  // no two cells overlap along an edge
      // separate squares would leave every edge outer (4 per body); a tiling leaves only the region's rim
      BOOST_TEST(t.outer_edges <= static_cast<std::size_t>(5 * K), t.outer_edges << " outer edges");
      BOOST_TEST(t.shared_edges >= 3 * bodies / 2, t.shared_edges << " shared edges");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()  // map_chart_cli_test
