// `rotlie md --scene liquid-water` end to end: the JSON contract of the issue, a state file written on
// the first run and reloaded by the next (which then gives the same numbers with another thread count),
// a dedicated rotor solved for the TIP3P body run from the saved state (a table solved for another
// body refused), and a state file of another system refused with one line, the file left as it was.
// One equilibration of 365 molecules (about 30 s of CPU): labelled cli, not fast.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(md_liquid_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

std::string liquid(const std::string& extra, const std::string& integrator = "MRDL") {
  return "md --scene liquid-water --integrator " + integrator + " --h 2 --T 0.02 --runs 1 --molecules 365 --state " +
         (scratch() / "w.state").string() + " " + extra;
}


}  // namespace

BOOST_AUTO_TEST_CASE(liquid_water_runs_saves_reloads_and_refuses_another_system) {
  // first run: equilibrates, writes the state, answers in JSON with the contract's fields
  const auto first = run(liquid("--threads 2 --json"));
  BOOST_TEST_REQUIRE(first.status == 0, first.err);
  const auto j = nlohmann::json::parse(first.out);
  for (const char* key : {"scene", "integrator", "h_fs", "f", "runs", "dE_over_dV_percent", "potential_kcal_per_mol", "ms_per_step"})
    BOOST_TEST(j.contains(key), key);
  BOOST_TEST(j["scene"] == "liquid-water");
  BOOST_TEST(j["integrator"] == "MRDL");
  BOOST_TEST(j["h_fs"].get<double>() == 2.0);
  BOOST_TEST(j["f"].get<int>() == 1);
  BOOST_TEST(j["runs"].get<int>() == 1);
  BOOST_TEST(j["dE_over_dV_percent"].size() == 2u);
  BOOST_TEST(j["dE_over_dV_percent"][0].get<double>() > 0);
  // TIP3P near 298 K: about −9.9 kcal/mol per molecule (Jorgensen et al. 1983: −9.86)
  BOOST_TEST(j["potential_kcal_per_mol"].get<double>() > -11.0);
  BOOST_TEST(j["potential_kcal_per_mol"].get<double>() < -8.5);
  BOOST_TEST(j["ms_per_step"].get<double>() > 0);
  BOOST_TEST_REQUIRE(fs::exists(scratch() / "w.state"));

  // second run from the saved state with one thread: the same numbers (no equilibration, thread-independent forces)
  const auto second = run(liquid("--threads 1 --json"));
  BOOST_TEST_REQUIRE(second.status == 0, second.err);
  const auto k = nlohmann::json::parse(second.out);
  BOOST_TEST(k["dE_over_dV_percent"][0].get<double>() == j["dE_over_dV_percent"][0].get<double>());
  BOOST_TEST(k["potential_kcal_per_mol"].get<double>() == j["potential_kcal_per_mol"].get<double>());

  // a step far beyond SIER4's stable range: a molecule spins up until the exact rotor refuses it (|ω| h > 2^60 rad);
  // said as a diverged run (exit 1), as a non-finite momentum is (this once ended the report's full section)
  const auto blown = run("md --scene liquid-water --integrator SIER4 --h 200 --T 2 --runs 1 --molecules 365 --state " +
                         (scratch() / "w.state").string());
  BOOST_TEST(blown.status == 1, blown.err);
  BOOST_TEST(blown.err == "rotlie: error: the run diverged (a molecule turns beyond the exact rotor's range) at h = 200 fs\n");

  // SIER2 with the dedicated rotor N2 BAC (2) solved for TIP3P, from the saved state (no second equilibration)
  const auto dedicated = run(liquid("--json", "SIER2/N2:BAC:2"));
  BOOST_TEST_REQUIRE(dedicated.status == 0, dedicated.err);
  const auto d = nlohmann::json::parse(dedicated.out);
  BOOST_TEST(d["integrator"] == "SIER2/N2:BAC:2");
  BOOST_TEST(d["f"].get<int>() == 1);
  BOOST_TEST_REQUIRE(d["dE_over_dV_percent"][0].is_number());
  const double ratio = d["dE_over_dV_percent"][0].get<double>();
  BOOST_TEST((std::isfinite(ratio) && ratio > 0), ratio);

  // the same scheme solved for the free-water body (another body): refused before any run
  const auto tables = scratch() / "tables";
  BOOST_TEST_REQUIRE(run("solve --family N --scheme N2 --perm BAC --inertia water --out " + tables.string()).status == 0);
  BOOST_TEST_REQUIRE(fs::exists(tables / "N2_BAC_2.scheme"));
  const std::string in_tables = "cd " + tables.string() + " && " + ROTLIE_BINARY + " " +
                                liquid("", "SIER2/N2_BAC_2.scheme") + " >" + (scratch() / "out").string() + " 2>" + (scratch() / "err").string();
  const int raw = std::system(in_tables.c_str());
  BOOST_TEST((WIFEXITED(raw) && WEXITSTATUS(raw) == 2));
  const std::string refused = slurp(scratch() / "err");
  BOOST_TEST(refused.find("was solved for the body") != std::string::npos, refused);
  BOOST_TEST(refused.find("--force") == std::string::npos, refused);  // md has no --force
  BOOST_TEST(std::count(refused.begin(), refused.end(), '\n') == 1);

  // the state of 365 molecules for a run of 400: one line, status 2, nothing on stdout, the file unchanged
  const std::string before = slurp(scratch() / "w.state");
  const auto other = run("md --scene liquid-water --integrator MRDL --h 2 --T 0.02 --runs 1 --molecules 400 --state " +
                         (scratch() / "w.state").string());
  BOOST_TEST(other.status == 2);
  BOOST_TEST(other.out.empty());
  BOOST_TEST(other.err.rfind("rotlie: error: ", 0) == 0u, other.err);
  BOOST_TEST(std::count(other.err.begin(), other.err.end(), '\n') == 1);
  BOOST_TEST(slurp(scratch() / "w.state") == before);
}

BOOST_AUTO_TEST_SUITE_END()  // md_liquid_cli_test
