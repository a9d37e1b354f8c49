// The neighbour check of a screened map (runs/map_neighbour_check.hpp): a body whose line names a
// best that a neighbour's best system beats there is replaced by the exact solver's line, and an
// exact map is left as it is. The shipped P map's own case at --grid 200 is in shipped_maps_test.
#include <boost/test/unit_test.hpp>

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/solver/body_grid.hpp"

using namespace rotlie;

namespace {

std::string system_of(const nlohmann::json& line) {
  const std::string label = line.at("best").get<std::string>();
  return label.substr(0, label.rfind(':'));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(map_neighbour_check_test)

BOOST_AUTO_TEST_CASE(tasks_survive_their_text) {
  const std::vector<runs::neighbour_task> tasks = {{12, "P8", "ABC"}, {7, "", ""}, {0, "N3", "BAC"}};
  const auto back = runs::tasks_from_text(runs::tasks_text(tasks));
  BOOST_TEST_REQUIRE(back.size() == tasks.size());
  for (std::size_t n = 0; n < tasks.size(); ++n) {
    BOOST_TEST(back[n].body == tasks[n].body);
    BOOST_TEST(back[n].scheme == tasks[n].scheme);
    BOOST_TEST(back[n].permutation == tasks[n].permutation);
  }
  BOOST_CHECK_THROW(runs::tasks_from_text("x P8 ABC\n"), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(an_exact_map_is_left_alone_and_a_worse_best_is_replaced) {
  // N's exact solver is cheap: the whole exact map at --grid 10
  const auto bodies = solver::asymmetric_grid(10);
  std::vector<std::string> exact;
  for (const auto& g : bodies) exact.push_back(runs::exact_map_line(g, "N"));
  auto lines = exact;
  const auto run = runs::local_neighbour_runner(bodies, "N");
  const auto untouched = runs::check_neighbours(bodies, lines, run);
  BOOST_TEST(untouched.replaced == 0u);
  BOOST_TEST(untouched.probes > 0u);
  BOOST_TEST(lines == exact);

  // A body inside a region of one best: its line is made to name another permutation's best, worse
  std::map<std::pair<int, int>, std::size_t> at;
  for (std::size_t k = 0; k < bodies.size(); ++k) at[{bodies[k].i, bodies[k].j}] = k;
  std::optional<std::size_t> target;
  nlohmann::json worse;
  for (std::size_t k = 0; k < bodies.size() && !target; ++k) {
    const auto line = nlohmann::json::parse(exact[k]);
    if (!line["best"].is_string()) continue;
    const auto right = at.find({bodies[k].i, bodies[k].j + 1});
    if (right == at.end() || !nlohmann::json::parse(exact[right->second])["best"].is_string() ||
        system_of(nlohmann::json::parse(exact[right->second])) != system_of(line))
      continue;
    for (const auto& p : line["permutations"])
      if (p["best"].is_string() && p["remainder"].get<double>() > 2 * line["remainder"].get<double>()) {
        worse = line;
        worse["best"] = p["best"];
        worse["remainder"] = p["remainder"];
        target = k;
        break;
      }
  }
  BOOST_TEST_REQUIRE(target.has_value());
  lines = exact;
  lines[*target] = worse.dump();
  const auto repaired = runs::check_neighbours(bodies, lines, run);
  BOOST_TEST(repaired.replaced == 1u);
  BOOST_TEST(lines == exact);  // the exact solver's line again, byte for byte
}

BOOST_AUTO_TEST_SUITE_END()  // map_neighbour_check_test
