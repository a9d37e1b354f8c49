// `rotlie md --scene liquid-water` end to end: the JSON contract of the issue, a state file written on
// the first run and reloaded by the next (which then gives the same numbers with another thread count),
// a dedicated rotor solved for the TIP3P body run from the saved state (a table solved for another
// body refused), and a state file of another system refused with one line, the file left as it was.
// One equilibration of 365 molecules over 1 ps (--equilibrate; about 5 s of CPU): labelled cli, not fast.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

BOOST_AUTO_TEST_SUITE(md_liquid_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

std::string liquid(const std::string& extra, const std::string& integrator = "MRDL") {
  return "md --scene liquid-water --integrator " + integrator + " --h 2 --T 0.02 --runs 1 --molecules 365 --equilibrate 1 --state " +
         (scratch() / "w.state").string() + " " + extra;
}


}  // namespace

// Whether `script` can give rotlie a terminal for stderr, where the progress lines go (it records them).
bool have_script() { return std::system("script -qec true /dev/null >/dev/null 2>&1 </dev/null") == 0; }

std::string replaced_line(const std::string& text, const std::string& prefix, const std::string& line) {
  const auto at = text.find("\n" + prefix);
  BOOST_REQUIRE(at != std::string::npos);
  return text.substr(0, at + 1) + line + text.substr(text.find('\n', at + 1));
}

BOOST_AUTO_TEST_CASE(liquid_water_runs_saves_reloads_and_refuses_another_system) {
  // a leftover of the temporary name every run once shared (a folder, so that writing to it fails): not this run's
  fs::create_directories(scratch() / "w.state.partial");
  // first run: equilibrates (its progress lines on a terminal when `script` can give it one), writes the
  // state, answers in JSON with the contract's fields
  const fs::path first_out = scratch() / "first.json", first_terminal = scratch() / "first.terminal";
  const bool terminal = have_script();
  const std::string first_command = std::string(ROTLIE_BINARY) + " " + liquid("--threads 2 --json") + " >" + first_out.string();
  const int first_raw = terminal ? std::system(("script -qefc '" + first_command + "' " + first_terminal.string() + " >/dev/null 2>&1 </dev/null").c_str())
                           : std::system((first_command + " 2>" + first_terminal.string() + " </dev/null").c_str());
  BOOST_TEST_REQUIRE((WIFEXITED(first_raw) && WEXITSTATUS(first_raw) == 0), slurp(first_terminal));
  BOOST_TEST(fs::is_directory(scratch() / "w.state.partial"));
  if (terminal) {
    // "equilibration 0.5 ps: T = 301.2 K, ...": six significant digits, never std::to_string's 0.500000
    const std::string shown = slurp(first_terminal);
    const std::regex progress("equilibration ([^ ]+) ps: T = ([^ ]+) K, V/N = ([^ ]+) kcal/mol");
    int lines = 0;
    for (auto it = std::sregex_iterator(shown.begin(), shown.end(), progress); it != std::sregex_iterator(); ++it, ++lines)
      for (int k = 1; k <= 3; ++k) {
        const std::string number = (*it)[k];
        BOOST_TEST(!std::regex_search(number, std::regex("\\.[0-9]*0$")), "a padded number: " << number);
        BOOST_TEST(std::isfinite(std::stod(number)), number);
      }
    BOOST_TEST(lines > 0, "no progress line on the terminal: " << shown.substr(0, 300));
  } else {
    BOOST_TEST_MESSAGE("no terminal from `script` here: the progress lines are not checked");
  }
  const auto j = nlohmann::json::parse(slurp(first_out));
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

  // damaged states: refused in one line (status 2), nothing on stdout, the file left as it was
  const fs::path state = scratch() / "w.state";
  const std::string rows_end = before.substr(0, before.size() - 1), last_row = rows_end.substr(rows_end.rfind('\n') + 1);
  const std::string cut = before.substr(0, before.size() - 1 - last_row.size());
  std::istringstream columns(last_row);
  std::vector<std::string> cells{std::istream_iterator<std::string>(columns), {}};
  const std::string row_of_19 = cut + last_row + " 0\n";
  // one momentum of 10^100 (once "0 ± 0 %, temperature 3e201 K"): the linear one px, the angular one Gz
  const auto with_cell = [&](std::size_t column, const std::string& value) {
    auto changed = cells;
    changed.at(column) = value;
    std::string text = cut;
    for (std::size_t c = 0; c < changed.size(); ++c) text += (c ? " " : "") + changed[c];
    return text + "\n";
  };
  const auto on_state = [&](const std::string& path) {
    return run("md --scene liquid-water --integrator MRDL --h 2 --T 0.02 --runs 1 --molecules 365 --state " + path);
  };
  for (const auto& [what, text] : std::vector<std::pair<std::string, std::string>>{
           {"molecules 365junk", replaced_line(before, "molecules ", "molecules 365junk")},
           {"time_fs nan", replaced_line(before, "time_fs ", "time_fs nan")},
           {"a row of 19 columns", row_of_19},
       }) {
    std::ofstream(state, std::ios::binary) << text;
    const auto r = on_state(state.string());
    BOOST_TEST_CONTEXT(what << ": status " << r.status << ", " << r.err) {
      BOOST_TEST(r.status == 2);
      BOOST_TEST(r.out.empty());
      BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      BOOST_TEST(slurp(state) == text);
    }
  }
  // a state without bound (/dev/zero) is refused, not read until memory runs out
  const auto zero = on_state("/dev/zero");
  BOOST_TEST(zero.status == 2, zero.err);
  BOOST_TEST(std::count(zero.err.begin(), zero.err.end(), '\n') == 1, zero.err);
  // a momentum of 10^100 is never a plain result. Angular (Gz): the rotational energy's squares overflow, a
  // failed run (exit 1). Linear (px): E is 10^200 kcal/mol and its fluctuation lost in round-off, so
  // ΔE/ΔV = 0 measures round-off: flagged in the JSON and said in one warning
  std::ofstream(state, std::ios::binary) << with_cell(17, "1e100");
  const auto spun = on_state(state.string());
  BOOST_TEST(spun.status == 1, spun.err);
  BOOST_TEST(spun.err.find("is not a number") != std::string::npos, spun.err);
  BOOST_TEST(std::count(spun.err.begin(), spun.err.end(), '\n') == 1, spun.err);
  std::ofstream(state, std::ios::binary) << with_cell(3, "1e100");
  const auto hot = run("md --scene liquid-water --integrator MRDL --h 2 --T 0.02 --runs 1 --molecules 365 --json --state " + state.string());
  BOOST_TEST_REQUIRE(hot.status == 0, hot.err);
  BOOST_TEST(nlohmann::json::parse(hot.out).at("round_off_floor").get<bool>());
  BOOST_TEST(hot.err.find("rotlie: warning: 1 of 1 runs have dE = ") == 0u, hot.err);
  BOOST_TEST(hot.err.find("dE/dV measures round-off") != std::string::npos, hot.err);
  BOOST_TEST(std::count(hot.err.begin(), hot.err.end(), '\n') == 1, hot.err);
  // a working run is not flagged
  BOOST_TEST(!j.at("round_off_floor").get<bool>());
  BOOST_TEST(!j.at("unstable").get<bool>());
  std::ofstream(state, std::ios::binary) << before;
}

// What can be checked before an equilibration is checked before it: a state that cannot be written, a step
// that cannot make a run. 4,000 molecules would equilibrate for many minutes: `timeout` ends a late refusal.
BOOST_AUTO_TEST_CASE(what_can_be_checked_is_refused_before_the_equilibration) {
  const std::string start = "timeout 60 " + std::string(ROTLIE_BINARY) + " md --scene liquid-water --integrator MRDL --molecules 4000 ";
  const fs::path fresh = scratch() / "fresh";
  fs::create_directories(fresh);
  for (const auto& [args, mention] : std::vector<std::pair<std::string, std::string>>{
           {"--h 2 --T 0.02 --runs 1 --state /proc/rotlie-no-such-folder/s.state", "/proc/rotlie-no-such-folder"},
           {"--h 2 --T 0.02 --runs 1 --state " + scratch().string() + "/no-such-folder/s.state", "no-such-folder"},
           {"--h 1e-12 --T 1 --runs 1 --state " + (fresh / "a.state").string(), "--h"},
           {"--h 2 --T 0.01 --runs 1 --state " + (fresh / "b.state").string(), "--T"},
       }) {
    const auto r = run_command(start + args);
    BOOST_TEST_CONTEXT(args << ": status " << r.status << ", " << r.err) {
      BOOST_TEST(r.status == 2);  // 124: timeout ended an equilibration the refusal came after
      BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u);
      BOOST_TEST(r.err.find(mention) != std::string::npos);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
  }
  BOOST_TEST(fs::is_empty(fresh));
}

BOOST_AUTO_TEST_SUITE_END()  // md_liquid_cli_test
