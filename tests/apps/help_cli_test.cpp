// What a new user reads first: every subcommand that `rotlie --help` lists names each option's value
// (a type such as KM, SECONDS or FILE, never CLI11's bare TEXT), shows the defaults, and ends with an
// "Example: rotlie …" line; each example runs as written, from an empty folder, with exit status 0.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(help_cli_test)

using namespace rotlie::test_cli;

namespace {

// The subcommands of `rotlie --help`, in its order.
std::vector<std::string> subcommands() {
  const auto r = run("--help");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  std::vector<std::string> names;
  std::istringstream in(r.out);
  bool listed = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "Subcommands:") {
      listed = true;
      continue;
    }
    if (!listed) continue;
    if (line.size() < 3 || line.compare(0, 2, "  ") != 0) break;
    names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

// The command after "Example: rotlie " in a help text, or "".
std::string example_of(const std::string& help) {
  const std::string mark = "\nExample: rotlie ";
  const auto at = help.find(mark);
  if (at == std::string::npos) return "";
  const auto start = at + mark.size();
  return help.substr(start, help.find('\n', start) - start);
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_subcommand_types_its_options_and_ends_with_an_example) {
  const auto names = subcommands();
  BOOST_TEST_REQUIRE(names.size() >= 16u);
  for (const auto& name : names) {
    const auto r = run(name + " --help");
    BOOST_TEST_CONTEXT("rotlie " << name << " --help") {
      BOOST_TEST(r.status == 0, r.err);
      BOOST_TEST(!std::regex_search(r.out, std::regex("\\bTEXT\\b")), r.out);
      const auto example = example_of(r.out);
      BOOST_TEST(example.rfind(name + " ", 0) == 0u, r.out);
      BOOST_TEST(r.out.find("Exit status") != std::string::npos, r.out);  // the statuses, after the example
    }
  }
}

BOOST_AUTO_TEST_CASE(defaults_are_shown_beside_the_type) {
  const auto remainder = run("remainder --help").out;
  BOOST_TEST(remainder.find("--perm PERM=ABC") != std::string::npos, remainder);
  BOOST_TEST(remainder.find("--order K=5") != std::string::npos, remainder);
  const auto binary = run("binary --help").out;
  for (const char* shown : {"--order ORDER=2", "--G NUMBER=6.67430e-20", "--h SECONDS", "--T SECONDS", "--every K=0",
                            "--accuracy REL[,RAD]=1e-3,1e-2", "--out FILE", "--separation KM"})
    BOOST_TEST(binary.find(shown) != std::string::npos, shown);
  // an option without a default shows none (and stays "not given" when left out)
  BOOST_TEST(binary.find("--separation KM=") == std::string::npos);
}

// Runs `name`'s example from an empty folder: exit 0, and it answers on stdout or writes its files.
void run_example_of(const std::string& name) {
  const auto example = example_of(run(name + " --help").out);
  const fs::path dir = scratch() / ("example-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (name == "sweep")  // the input its footer describes
    std::ofstream(dir / "runs.jsonl") << R"({"system": "didymos", "integrator": "SIER4", "h": 60, "T": 3600})" << "\n";
  const auto r = run_command("cd " + dir.string() + " && " + ROTLIE_BINARY + " " + example);
  BOOST_TEST(r.status == 0, "rotlie " << example << " → " << r.status << ": " << r.err);
  // it answers on stdout or writes its files (report, map, sweep)
  const auto made = std::distance(fs::directory_iterator(dir), fs::directory_iterator()) > (name == "sweep" ? 1 : 0);
  BOOST_TEST((!r.out.empty() || made), "rotlie " << example << " printed and wrote nothing");
  fs::remove_all(dir);
}

// best's example solves its body's three families (about 25 s): it runs in help_examples_cli_test (slow)
const std::string costly_example = "best";

BOOST_AUTO_TEST_CASE(every_example_runs_as_written) {
  for (const auto& name : subcommands())
    if (name != costly_example) run_example_of(name);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(help_examples_cli_test)

BOOST_AUTO_TEST_CASE(the_costly_example_runs_as_written) { help_cli_test::run_example_of(help_cli_test::costly_example); }

BOOST_AUTO_TEST_SUITE_END()
