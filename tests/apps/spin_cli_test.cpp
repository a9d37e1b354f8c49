// `rotlie spin` end to end: the JSON contract (issue 24), the initial state of the contract seen in a
// zero-length-like run, and bad input as one line on stderr with exit status 2.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

BOOST_AUTO_TEST_SUITE(spin_cli_test)

using namespace rotlie::test_cli;

namespace {

nlohmann::json spin_json(const std::string& args) {
  const auto r = run("spin " + args + " --json");
  BOOST_TEST_REQUIRE(r.status == 0, "rotlie spin " << args << ": " << r.err);
  return nlohmann::json::parse(r.out);
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_json_has_the_contracts_fields) {
  const auto j = spin_json("--body Hyperion --e 0.1 --integrator SIER4 --h 1/1000 --T 2");
  for (const char* key : {"body", "e", "integrator", "h", "T", "Q", "omega_body", "theta", "cpu_s"}) BOOST_TEST(j.contains(key), key);
  BOOST_TEST(j["body"] == "Hyperion");
  BOOST_TEST(j["integrator"] == "SIER4");
  BOOST_TEST(j["h"].get<double>() == 0.001);
  BOOST_TEST(j["T"].get<double>() == 2.0);
  BOOST_TEST(j["steps"].get<long>() == 2000);
  BOOST_TEST(j["Q"].size() == 3u);
  // the final attitude is a rotation, and with obliquity 0 a rotation about z by theta
  const double theta = j["theta"].get<double>();
  BOOST_TEST(std::abs(j["Q"][0][0].get<double>() - std::cos(theta)) < 1e-12);
  BOOST_TEST(std::abs(j["Q"][1][0].get<double>() - std::sin(theta)) < 1e-12);
  BOOST_TEST(std::abs(j["Q"][2][2].get<double>() - 1) < 1e-12);
  BOOST_TEST(std::abs(j["omega_body"][0].get<double>()) < 1e-12);
}

BOOST_AUTO_TEST_CASE(the_initial_state_follows_the_contract) {
  // one tiny step: Q ≈ R_x(obliquity) R_z(theta0), omega_body ≈ (0, 0, omega0)
  const double th = 0.4, ob = 0.3, w = 1.5;
  const auto j = spin_json("--body Moon --e 0.0549 --integrator SIER2 --h 1e-9 --T 1e-9 --theta0 0.4 --obliquity 0.3 --omega0 1.5");
  const double expected[3][3] = {{std::cos(th), -std::sin(th), 0},
                                 {std::cos(ob) * std::sin(th), std::cos(ob) * std::cos(th), -std::sin(ob)},
                                 {std::sin(ob) * std::sin(th), std::sin(ob) * std::cos(th), std::cos(ob)}};
  // over 2π·1e-9 the body turns by ω t ≈ 1e-8
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(j["Q"][i][k].get<double>() - expected[i][k]) < 2e-8, i << k);
  BOOST_TEST(std::abs(j["omega_body"][2].get<double>() - w) < 1e-8);
}

BOOST_AUTO_TEST_CASE(every_integrator_family_runs_and_agrees) {
  // Mercury held in 3:2 over 4 orbits: the spin angle returns to within 0.05 rad of 0 (6 turns), for all
  for (const char* name : {"SIER2", "SIER4", "MRDL", "SIER4/RS4-S5-McLachlan:CBA", "odeint-dopri5:1e-11", "odeint-rkf78"}) {
    const auto j = spin_json(std::string("--body Mercury --e 0.2056 --omega0 1.5 --h 1/500 --T 4 --integrator ") + name);
    BOOST_TEST(std::abs(j["theta"].get<double>()) < 0.05, name);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_is_one_line_and_exit_two) {
  for (const char* args : {"--body 0.8,0.6,1 --e 0.1 --integrator SIER2 --h 1/100 --T 1",     // A > B
                           "--body Hyperion --e 1 --integrator SIER2 --h 1/100 --T 1",        // e >= 1
                           "--body Hyperion --e 0.1 --integrator SIER2 --h 0 --T 1",          // h <= 0
                           "--body Hyperion --e 0.1 --integrator SIER2 --h -1/100 --T 1",
                           "--body Vulcan --e 0.1 --integrator SIER2 --h 1/100 --T 1",        // unknown body
                           "--body Hyperion --e 0.1 --integrator LEAP --h 1/100 --T 1",       // unknown integrator
                           "--body Hyperion --e 0.1 --integrator SIER2/XYZ --h 1/100 --T 1",  // unknown rotor
                           "--body Hyperion --e nan --integrator SIER2 --h 1/100 --T 1",      // NaN
                           "--body Hyperion --e 0.1 --integrator SIER2 --h 1/100 --T nan",
                           "--body Hyperion --e 0.1 --integrator SIER2 --h 1/100 --T 1 --theta0 nan",
                           "--body Hyperion --e 0.1 --integrator odeint-rkf78 --h 1/100 --T 1 --scalar float128",
                           "--body Hyperion --e 0.1 --integrator SIER2 --h 1/100"}) {  // --T missing
    const auto r = run(std::string("spin ") + args);
    BOOST_TEST(r.status == 2, args << ": status " << r.status);
    BOOST_TEST(r.out.empty(), args);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, args << ": " << r.err);
    BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u, args << ": " << r.err);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // spin_cli_test
