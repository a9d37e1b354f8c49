// The cells the body-set maps are drawn with (Figs. 7–10): every asymmetric body of a grid a closed
// quadrilateral of positive area, and the cells tiling the triangle between them (edges shared by two
// cells, only the region's rim used once), whichever series each body falls in. The charts that use
// them, through the binary, are map_chart_cli_test's (slow).
#include <boost/test/unit_test.hpp>

#include "tiling.hpp"

#include <vector>

#include "rotlie/reports/body_cells.hpp"
#include "rotlie/solver/body_grid.hpp"

BOOST_AUTO_TEST_SUITE(body_cells_test)

using rotlie::test_tiling::point;
using rotlie::test_tiling::tiling_of;

BOOST_AUTO_TEST_CASE(the_cells_of_a_grid_tile_the_triangle) {
  for (const int K : {12, 40}) {  // the CLI test's grid and the default report's N grid
    BOOST_TEST_CONTEXT("--grid " << K) {
      rotlie::reports::body_cells cells(K);
      // three series, as a categorical chart splits the bodies by their best integrator
      std::vector<std::vector<double>> x(3), y(3);
      const auto bodies = rotlie::solver::asymmetric_grid(K);
      for (const auto& b : bodies) cells.add(b.i, b.j, x[(b.i + 2 * b.j) % 3], y[(b.i + 2 * b.j) % 3]);
      std::vector<std::vector<point>> series(3);
      for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t p = 0; p < x[k].size(); ++p) series[k].push_back({x[k][p], y[k][p]});
      const auto t = tiling_of(series);
      if (K == 12) BOOST_TEST(bodies.size() == 132u);  // the map's count at --grid 12
      BOOST_TEST(t.cells == bodies.size());
      BOOST_TEST(t.open_cells == 0u);
      BOOST_TEST(t.smallest_area > 0);
      BOOST_TEST(t.overused_edges == 0u);  // no two cells overlap along an edge
      // separate squares would leave every edge outer (4 per body); a tiling leaves only the region's rim
      BOOST_TEST(t.outer_edges <= static_cast<std::size_t>(5 * K), t.outer_edges << " outer edges");
      BOOST_TEST(t.shared_edges >= 3 * bodies.size() / 2, t.shared_edges << " shared edges");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()  // body_cells_test
