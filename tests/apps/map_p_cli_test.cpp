// The P map at a coarse grid end to end: it names the best that `solve` finds for the body. At
// (s, t) = (3/5, 2/5), I = (11/25, 4/5, 1), the screened path once said P6:BAC:3 (‖H_R5‖ 1.0435e-3)
// where P1:ABC:3 has 8.487e-4; coarse grids now take the exact solver (about 2 CPU minutes).
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(map_p_cli_test)

using namespace rotlie::test_cli;

BOOST_AUTO_TEST_CASE(the_p_map_at_grid_5_names_the_best_that_solve_finds) {
  const auto map = run("map --family P --grid 5 --json");
  BOOST_REQUIRE_MESSAGE(map.status == 0, map.err);
  std::istringstream lines(map.out);
  std::string line;
  int checked = 0;
  while (std::getline(lines, line)) {
    const auto body = nlohmann::json::parse(line);
    const bool wanted = (body.at("s") == "3/5" || body.at("s") == "4/5") && body.at("t") == "2/5";
    if (!wanted) continue;
    const auto& I = body.at("I");
    const std::string inertia = I[0].get<std::string>() + "," + I[1].get<std::string>() + "," + I[2].get<std::string>();
    const auto solved = run("solve --family P --inertia " + inertia + " --json");
    BOOST_REQUIRE_MESSAGE(solved.status == 0, solved.err);
    const auto best = nlohmann::json::parse(solved.out).at("solutions").at(0);
    BOOST_TEST_CONTEXT("body " << inertia) {
      BOOST_TEST(body.at("best").get<std::string>() == best.at("scheme").get<std::string>() + ":" + best.at("perm").get<std::string>() +
                                                            ":" + std::to_string(best.at("label").get<int>()));
      BOOST_TEST(body.at("remainder").get<double>() == best.at("analytic_remainder").get<double>(), boost::test_tools::tolerance(1e-12));
    }
    ++checked;
  }
  BOOST_TEST(checked == 2);
}

BOOST_AUTO_TEST_SUITE_END()  // map_p_cli_test
