// `rotlie md` end to end: the JSON contract of both scenes, the same seed giving the same numbers,
// --h as the step itself (h/f reported beside it) and a dedicated rotor resolved for the water body.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(md_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

nlohmann::json md_json(const std::string& args) {
  const auto r = run("md " + args + " --json");
  BOOST_TEST_REQUIRE(r.status == 0, "rotlie md " << args << ": " << r.err);
  return nlohmann::json::parse(r.out);
}

}  // namespace

BOOST_AUTO_TEST_CASE(free_water_json_has_the_contracts_fields) {
  const auto j = md_json("--scene free-water --integrator MRDL --h 4 --T 1 --runs 5 --seed 9");
  for (const char* key : {"scene", "integrator", "h_fs", "f", "runs", "seed", "tau_ps"}) BOOST_TEST(j.contains(key), key);
  BOOST_TEST(j["scene"] == "free-water");
  BOOST_TEST(j["integrator"] == "MRDL");
  BOOST_TEST(j["h_fs"].get<double>() == 4.0);
  BOOST_TEST(j["f"].get<int>() == 1);
  BOOST_TEST(j["runs"].get<int>() == 5);
  BOOST_TEST(j["seed"].get<int>() == 9);
  BOOST_TEST(j["steps"].get<int>() == 250);
  BOOST_TEST(j["tau_ps"].get<double>() > 0);
}

BOOST_AUTO_TEST_CASE(dipole_json_has_the_contracts_fields_and_h_is_the_step) {
  const auto j = md_json("--scene dipole-field --integrator SIER4 --h 16.8 --T 2 --runs 3");
  for (const char* key : {"scene", "integrator", "h_fs", "f", "dH_over_dV_percent", "dLz_over_Lz", "cpu_s_per_ps"})
    BOOST_TEST(j.contains(key), key);
  BOOST_TEST(j["f"].get<int>() == 4);
  BOOST_TEST(j["h_fs"].get<double>() == 16.8);
  BOOST_TEST(std::abs(j["h_over_f_fs"].get<double>() - 4.2) < 1e-12);
  BOOST_TEST(j["dH_over_dV_percent"].size() == 2u);
  BOOST_TEST(j["dLz_over_Lz"].size() == 2u);
  BOOST_TEST(j["dH_over_dV_percent"][0].get<double>() > 0);
}

BOOST_AUTO_TEST_CASE(the_same_seed_gives_the_same_json) {
  for (const char* args : {"--scene dipole-field --integrator SIER2 --h 4.2 --T 2 --runs 4 --seed 11",
                           "--scene free-water --integrator SEJ4 --h 8 --T 1 --runs 4 --seed 11"}) {
    auto a = md_json(args), b = md_json(args), c = md_json(std::string(args) + "2");
    for (auto* j : {&a, &b, &c}) j->erase("cpu_s_per_ps");  // the one measured, not computed, value
    BOOST_TEST(a == b, args);
    c["seed"] = a["seed"];
    BOOST_TEST(a != c, args << " (another seed, other numbers)");
  }
}

BOOST_AUTO_TEST_CASE(a_dedicated_rotor_is_solved_for_the_water_molecule) {
  const auto j = md_json("--scene free-water --integrator SIER2/P1:BAC:5 --h 8 --T 1 --runs 4");
  BOOST_TEST(j["integrator"] == "SIER2/P1:BAC:5");
  BOOST_TEST(j["tau_ps"].get<double>() > 1000);  // a 4th-order rotor: far beyond MRDL's picoseconds
}

BOOST_AUTO_TEST_CASE(a_rotor_table_solved_for_another_body_is_refused_without_an_override_hint) {
  // md has no --force: the refusal must not suggest one
  const fs::path dir = scratch() / "foreign";
  fs::create_directories(dir);
  BOOST_TEST_REQUIRE(run("solve --family N --scheme N2 --perm BAC --inertia 1/2,4/5,1 --out " + dir.string()).status == 0);
  const auto r = run("md --scene free-water --integrator SIER2/" + (dir / "N2_BAC_2.scheme").string() + " --h 8 --T 1 --runs 2");
  fs::remove_all(dir);
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(r.err.find("was solved for the body") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("--force") == std::string::npos, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.out.empty());
}

BOOST_AUTO_TEST_SUITE_END()  // md_cli_test
