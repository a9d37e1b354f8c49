// The full-resolution maps shipped under data/maps-K200 (scripts/make-full-data.sh): each is a whole
// map of its family at --grid 200, and at bodies drawn at random from it the exact solver, run again
// here, gives the same best integrator, label, reference and ratio (runs/map_check). A family not
// shipped yet is skipped with a message. And the body where the screened P rows named a best that is
// not (s = 121/200, t = 83/200) gets the exact best from the neighbour check.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "rotlie/runs/map_check.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/shipped_data.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/screened_map.hpp"

using namespace rotlie;

BOOST_AUTO_TEST_SUITE(shipped_maps_test)

BOOST_AUTO_TEST_CASE(the_shipped_maps_are_whole_and_agree_with_the_exact_solver) {
  // bodies re-solved per family, within the slow suite's budget (a P body takes the exact solver about
  // 7 CPU s): the 200-body check of the screened P path at K = 200 is bench/map_check's, recorded in
  // data/README.md; N's continuation and R's exact solver were checked at every body of coarse grids
  const std::map<std::string, std::size_t> checks = {{"N", 100}, {"R", 20}, {"P", 20}};
  int shipped = 0;
  for (const auto& [family, count] : checks) {
    const auto file = runs::shipped_map(family);
    if (!file) {
      rotlie::test::skip("no shipped map of family " + family + " (data/maps-K200)");
      continue;
    }
    ++shipped;
    BOOST_TEST_CONTEXT(file->string()) {
      const auto m = runs::read_map_contents(*file);
      BOOST_TEST_REQUIRE(m.has_value());
      BOOST_TEST(m->family == family);
      BOOST_TEST(m->K == 200);
      // every asymmetric body once: (K+1)^2 grid points less the symmetric tops
      std::set<std::pair<std::string, std::string>> places;
      for (const auto& b : m->bodies) places.emplace(b.at("s").get<std::string>(), b.at("t").get<std::string>());
      BOOST_TEST(places.size() == m->bodies.size());
      BOOST_TEST(m->bodies.size() == 39800u);
      const auto r = runs::check_map_lines(family, m->K, m->bodies, count, 2026);
      BOOST_TEST(r.checked == static_cast<int>(count));
      BOOST_TEST(r.disagreements == 0);
      for (const auto& d : r.differences) BOOST_TEST_MESSAGE(d);
    }
  }
  BOOST_TEST(shipped >= 1, "no shipped map found at all");
}

BOOST_AUTO_TEST_CASE(the_screened_p_map_at_s_121_t_83_gets_the_exact_best) {
  const auto shipped = runs::shipped_map("P");
  if (!shipped) {
    rotlie::test::skip("no shipped P map (data/maps-K200)");
    return;
  }
  const auto m = runs::read_map_contents(*shipped);
  BOOST_TEST_REQUIRE(m.has_value());
  const int K = 200;
  const auto grid = solver::asymmetric_grid(K);
  // The window: rows 120–122, columns 82–84; rows 120 and 122 as shipped, row 121 as its screened
  // row gives it (the whole row is carried, as the map carries it)
  std::vector<solver::grid_body> row121, window;
  for (const auto& g : grid) {
    if (g.i == 121) row121.push_back(g);
    if (g.i >= 120 && g.i <= 122 && g.j >= 82 && g.j <= 84) window.push_back(g);
  }
  const auto points = solver::screened_map_points(row121, "P");
  std::map<std::pair<int, int>, std::string> line_at;
  for (std::size_t k = 0; k < row121.size(); ++k)
    line_at[{row121[k].i, row121[k].j}] = runs::map_line(row121[k], points[k]).dump();
  for (const auto& b : m->bodies) {
    const auto ij = runs::map_line_indices(b, K);
    if (ij && ij->first != 121 && ij->first >= 120 && ij->first <= 122 && ij->second >= 82 && ij->second <= 84) line_at[*ij] = b.dump();
  }
  std::vector<std::string> lines;
  std::size_t target = 0;
  for (const auto& g : window) {
    if (g.i == 121 && g.j == 83) target = lines.size();
    lines.push_back(line_at.at({g.i, g.j}));
  }
  BOOST_TEST_MESSAGE("screened row 121 at t = 83/200: " << nlohmann::json::parse(lines[target])["best"]);
  const auto counts = runs::check_neighbours(window, lines, runs::local_neighbour_runner(window, "P"));
  BOOST_TEST(counts.replaced >= 1u);
  const auto checked = nlohmann::json::parse(lines[target]);
  const auto exact = nlohmann::json::parse(runs::exact_map_line(window[target], "P"));
  BOOST_TEST(checked["best"] == exact["best"]);
  BOOST_TEST(checked["best"] == "P1:ABC:3");  // the exact solver's best there (bench/map_check, data/README.md)
  BOOST_TEST(checked["remainder"].get<double>() == exact["remainder"].get<double>());
}

BOOST_AUTO_TEST_SUITE_END()  // shipped_maps_test
