// `rotlie binary --gubas-config FILE`: a GUBAS configuration (the keys and values of GUBAS's
// example/hou_config.cfg, fork meyeralexj/gubas at 8db57ff4, with the Perturbed-Model ellipsoid as the
// primary) runs in rotlie's units; an option it sets given beside it, or one describing the start
// another way, is refused in one line (exit 2), as is an option without a rotlie counterpart.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

BOOST_AUTO_TEST_SUITE(binary_gubas_cli_test)

using namespace rotlie::test_cli;

namespace {

std::string config(const std::string& integrator_flag = "2") {
  return "[Gravity Parameter]\nG: 6.67e-11\n"
         "[Initial Conditions]\nFahnestock Input File Flag: 0\n"
         "Relative Position X: 1200.0\nRelative Position Y: 0.\nRelative Position Z: 0.\n"
         "Relative Velocity X: 0.\nRelative Velocity Y: 0.175704287113523\nRelative Velocity Z: 0.\n"
         "Primary Angular Velocity X: 0.0\nPrimary Angular Velocity Y: 0.0\nPrimary Angular Velocity Z: 0.000772269580528\n"
         "Secondary Angular Velocity X: 0.0\nSecondary Angular Velocity Y: 0.0\nSecondary Angular Velocity Z: 0.000146420239261\n"
         "B into A Euler Flag: 1\nB into A Euler 1 X: 0.\nB into A Euler 2 Y: 0.\nB into A Euler 3 Z: 0.\n"
         "A into N Euler Flag: 1\nA into N Euler 1 X: 0.\nA into N Euler 2 Y: 0.\nA into N Euler 3 Z: 0.\n"
         "[Integration Settings]\nStart Time: 0.0\nFinal Time: 7200.\nIntegrator Flag: " + integrator_flag + "\nFixed Time Step: 30.\nAbsolute Tolerance: 1.e-15\n"
         "[Body Model Definitions]\nPrimary Shape Flag: 1\nSecondary Shape Flag: 1\n"
         "Primary Semi-Major Axis: 398.88\nPrimary Semi-Intermediate Axis: 391.30\nPrimary Semi-Minor Axis: 383.48\n"
         "Secondary Semi-Major Axis: 103.16\nSecondary Semi-Intermediate Axis: 79.35\nSecondary Semi-Minor Axis: 66.13\n"
         "Primary Density: 2.203111036687207\nSecondary Density: 2.203111036687207\n"
         "[Mutual Gravity Expansion Parameters]\nGravity Expansion Truncation Order: 4\n"
         "Primary Inertia Integral Truncation Order: 4\nSecondary Inertia Integral Truncation Order: 4\n"
         "[Additional Forces and Perturbations]\nFlyby: 0\nHeliocentric Orbit: 0\nSolar Gravity: 0\nTidal Torque: 0\n";
}

std::string written(const std::string& name, const std::string& text) {
  const auto p = scratch() / name;
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_gubas_configuration_runs_in_rotlies_units) {
  const auto r = run("binary --gubas-config " + written("hou_config.cfg", config()) + " --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j["integrator"].get<std::string>() == "LGVI");
  BOOST_TEST(j["h"].get<double>() == 30.0);
  BOOST_TEST(j["T"].get<double>() == 7200.0);
  BOOST_TEST(j["order"].get<int>() == 4);
  BOOST_TEST(std::abs(j["G"].get<double>() - 6.67e-20) < 1e-34);
  BOOST_TEST(j["primary"].get<std::string>() == "ellipsoid:0.39888,0.3913,0.38348");
  const double mass = 2203.111036687207e9 * 4 * std::acos(-1.0) / 3 * 0.39888 * 0.3913 * 0.38348;  // kg
  BOOST_TEST(std::abs(j["masses"][0].get<double>() / mass - 1) < 1e-13);
  // the same run from rotlie's own options gives the same numbers
  const auto state = written("start.json", R"({"r": [1.2, 0, 0], "v": [0, 0.000175704287113523, 0], "Q1": [[1,0,0],[0,1,0],[0,0,1]],
      "Q2": [[1,0,0],[0,1,0],[0,0,1]], "omega1": [0, 0, 0.000772269580528], "omega2": [0, 0, 0.000146420239261]})");
  const auto same = run("binary --primary ellipsoid:0.39888,0.3913,0.38348 --secondary ellipsoid:0.10316,0.07935,0.06613 --density " +
                        j["densities"][0].dump() + " --G 6.67e-20 --order 4 --integrator LGVI --h 30 --T 7200 --state " + state + " --json");
  BOOST_TEST_REQUIRE(same.status == 0, same.err);
  const auto k = nlohmann::json::parse(same.out);
  BOOST_TEST(j["r"] == k["r"]);
  BOOST_TEST(j["Q2"] == k["Q2"]);
}

BOOST_AUTO_TEST_CASE(options_the_configuration_sets_are_refused_beside_it) {
  const auto cfg = written("hou_config.cfg", config());
  expect_refusal("binary --gubas-config " + cfg + " --integrator RK4", "--integrator is set by --gubas-config (from GUBAS's 'Integrator Flag')");
  expect_refusal("binary --gubas-config " + cfg + " --T 60", "--T is set by --gubas-config (from GUBAS's 'Final Time')");
  expect_refusal("binary --gubas-config " + cfg + " --system didymos", "--system and --gubas-config exclude each other");
  expect_refusal("binary --gubas-config " + cfg + " --separation 1.2", "--separation and --gubas-config exclude each other");
  expect_refusal("binary --system didymos --h 60 --T 600", "--integrator is required");  // without a config, as before
  expect_refusal("binary --gubas-config " + written("abm.cfg", config("4")),
                 "GUBAS option 'Integrator Flag' = 4 (the Adams-Bashforth-Moulton predictor-corrector) has no rotlie counterpart");
  expect_refusal("binary --gubas-config " + (scratch() / "missing.cfg").string(), "--gubas-config");
  // options it does not set go with it
  const auto r = run("binary --gubas-config " + cfg + " --every 120 --json --no-error-estimate");
  BOOST_TEST(r.status == 0, r.err);
}

BOOST_AUTO_TEST_SUITE_END()
