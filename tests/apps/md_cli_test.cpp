// `rotlie md` end to end: the JSON contract of both scenes, the same seed giving the same numbers,
// --h as the step itself (h/f reported beside it) and a dedicated rotor resolved for the water body.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"
#include "md_cli_support.hpp"

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
  // nor name an option md does not have: the body is the scene's (this once said "not for --inertia")
  BOOST_TEST(r.err.find("--inertia") == std::string::npos, r.err);
  BOOST_TEST(r.err.find("not for this run's body (") != std::string::npos, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.out.empty());
}

// A run whose numbers do not mean what they say is not reported as a plain result.
BOOST_AUTO_TEST_CASE(statistics_beyond_the_scalars_range_are_a_failure_not_zero) {
  // a dipole of 10^100 D: the energies' squares overflow; this once printed dH/dV = 0 ± 0 % with exit 0
  const auto r = run("md --scene dipole-field --integrator MRDL --h 8 --dipole 1e100 --runs 3 --T 1");
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.err.find("no run has a finite dH/dV") != std::string::npos, r.err);
  BOOST_TEST(r.out.find("0 ± 0") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_step_beyond_the_stable_range_is_flagged_and_warned) {
  const auto r = run("md --scene dipole-field --integrator MRDL --h 1e8 --runs 3 --T 1e6 --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("dH_over_dV_percent")[0].get<double>() > 100);
  BOOST_TEST(j.at("unstable").get<bool>());
  BOOST_TEST(!j.at("round_off_floor").get<bool>());
  BOOST_TEST(r.err.find("beyond the integrator's stable range") != std::string::npos, r.err);
  // a working step is neither
  const auto good = md_json("--scene dipole-field --integrator SIER4 --h 16.8 --runs 3 --T 5");
  BOOST_TEST(!good.at("unstable").get<bool>());
  BOOST_TEST(!good.at("round_off_floor").get<bool>());
}

BOOST_AUTO_TEST_CASE(a_step_lost_in_round_off_is_flagged_and_warned) {
  // 10^-50 fs: each step turns the molecule by far less than ε (this once printed 23,671 % as a result)
  const auto r = run("md --scene dipole-field --integrator SIER4 --h 1e-50 --runs 2 --T 1e-48 --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("round_off_floor").get<bool>());
  BOOST_TEST(!j.at("unstable").get<bool>());
  BOOST_TEST(r.err.find("measures round-off") != std::string::npos, r.err);
  // free water with the exact rotor: no integrator error at all, δ is the scalar's round-off
  const auto w = run("md --scene free-water --integrator SIER2 --h 8 --runs 2 --T 1 --json");
  BOOST_TEST_REQUIRE(w.status == 0, w.err);
  BOOST_TEST(nlohmann::json::parse(w.out).at("round_off_floor").get<bool>());
  BOOST_TEST(w.err.find("tau measures round-off") != std::string::npos, w.err);
  // free water at 10^-50 fs: δ grows to 6e-10 over 10^6 steps (about 3 ε per step), far above 1000 ε but all
  // round-off (a τ of 1.6e-39 ps was once reported without a word)
  const auto tiny = run("md --scene free-water --integrator SIER4 --h 1e-50 --runs 2 --T 1e-47 --json");
  BOOST_TEST_REQUIRE(tiny.status == 0, tiny.err);
  BOOST_TEST(nlohmann::json::parse(tiny.out).at("round_off_floor").get<bool>());
  BOOST_TEST(tiny.err.find("within what the scalar's round-off reaches in 1000000 steps") != std::string::npos, tiny.err);
  // a working step is not flagged
  BOOST_TEST(!md_json("--scene free-water --integrator SIER4/RS4-S5-McLachlan:CBA --h 2 --runs 2 --T 1")
                  .at("round_off_floor")
                  .get<bool>());
}

BOOST_AUTO_TEST_CASE(the_error_of_one_run_is_unknown_not_zero) {
  const auto j = md_json("--scene dipole-field --integrator SIER2 --h 8 --runs 1 --T 1");
  BOOST_TEST(j.at("dH_over_dV_percent")[1].is_null());
  BOOST_TEST(j.at("dLz_over_Lz")[1].is_null());
  const auto text = run("md --scene dipole-field --integrator SIER2 --h 8 --runs 1 --T 1");
  BOOST_TEST(text.out.find("± unknown (one run)") != std::string::npos, text.out);
  BOOST_TEST(text.out.find("± 0 ") == std::string::npos, text.out);
  const auto w = md_json("--scene free-water --integrator MRDL --h 8 --runs 1 --T 1");
  BOOST_TEST(w.at("tau_error_ps").is_null());
  // and in the text: tau's error is unknown, never "± nan" (free-water once printed tau = 13.84 ± nan)
  const auto free_text = run("md --scene free-water --integrator MRDL --h 8 --runs 1 --T 1");
  BOOST_TEST(free_text.out.find("tau = ") != std::string::npos, free_text.out);
  BOOST_TEST(free_text.out.find("± unknown (one run)") != std::string::npos, free_text.out);
  BOOST_TEST(free_text.out.find("nan") == std::string::npos, free_text.out);
}

BOOST_AUTO_TEST_SUITE_END()  // md_cli_test
