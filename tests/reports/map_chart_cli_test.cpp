// The report's body-set maps through the binary: drawn as continuous maps over the triangle, each body
// a closed cell and the cells tiling the region between them, not rows of separate squares with white
// gaps (Fig. 8 at --grid 40 once was). Read from the CSV written beside each chart (the numbers gnuplot
// drew). About a minute: the maps section also checks 4 bodies of the shipped P map exactly; labelled
// slow (README command 1 and the quick report's run cover the section), while the cells themselves are
// checked in the fast body_cells_test.
#include <boost/test/unit_test.hpp>

#include "../apps/cli_support.hpp"
#include "tiling.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(map_chart_cli_test)

namespace fs = std::filesystem;
using namespace rotlie::test_cli;

namespace {

using rotlie::test_tiling::point;
using rotlie::test_tiling::tiling_of;

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
        if (name.find("ratio = 1") == std::string::npos) {  // the contour's segments aside
          BOOST_TEST_REQUIRE(points.size() % 5 == 0u);
          cells.push_back(points);
        }
      const auto t = tiling_of(cells);
      BOOST_TEST(t.cells == bodies);
      BOOST_TEST(t.open_cells == 0u);
      BOOST_TEST(t.smallest_area > 0);
      BOOST_TEST(t.overused_edges == 0u);  // no two cells overlap along an edge
      // separate squares would leave every edge outer (4 per body); a tiling leaves only the region's rim
      BOOST_TEST(t.outer_edges <= static_cast<std::size_t>(5 * K), t.outer_edges << " outer edges");
      BOOST_TEST(t.shared_edges >= 3 * bodies / 2, t.shared_edges << " shared edges");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()  // map_chart_cli_test
