// `rotlie binary --every K`: the trajectory goes to --out FILE (JSON lines, or CSV for a .csv name),
// written whole at the end with the text summary alone on stdout, or with --json and no --out to
// stdout before the summary's line; --every with neither is refused (exit 2), as is --out without
// --every or into what cannot be written.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(binary_out_cli_test)

using namespace rotlie::test_cli;

namespace {

const std::string run_args = "binary --system didymos --integrator KEPLER2 --h 60 --T 600 --every 5";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = scratch() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_without_out_or_json_is_refused_naming_both) {
  const auto r = run(run_args);
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(r.out.empty());
  BOOST_TEST(r.err.find("--out FILE") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("--json") != std::string::npos, r.err);
}

BOOST_AUTO_TEST_CASE(the_file_holds_the_lines_json_prints_and_stdout_the_summary) {
  const fs::path dir = fresh_folder("jsonl");
  const auto on_stdout = run(run_args + " --json");
  BOOST_TEST_REQUIRE(on_stdout.status == 0, on_stdout.err);
  auto expected = lines_of(on_stdout.out);
  BOOST_TEST_REQUIRE(expected.size() == 4u);  // t = 0, 300, 600, then the run's JSON
  expected.pop_back();

  const auto text = run(run_args + " --out " + (dir / "trajectory.jsonl").string());
  BOOST_TEST_REQUIRE(text.status == 0, text.err);
  BOOST_TEST(lines_of(slurp(dir / "trajectory.jsonl")) == expected, boost::test_tools::per_element());
  BOOST_TEST(text.out.rfind("binary didymos", 0) == 0u, text.out);  // the text summary, alone
  BOOST_TEST(text.out.find('{') == std::string::npos, text.out);
  BOOST_TEST(entries(dir) == std::set<std::string>{"trajectory.jsonl"});  // no temporary left

  // with --json and --out: the file again, stdout one JSON document (the summary, no trajectory)
  const auto json = run(run_args + " --json --out " + (dir / "trajectory.jsonl").string());
  BOOST_TEST_REQUIRE(json.status == 0, json.err);
  const auto summary = nlohmann::json::parse(json.out);
  BOOST_TEST(summary.at("t").get<double>() == 600.0);
  BOOST_TEST(lines_of(slurp(dir / "trajectory.jsonl")) == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_csv_name_gives_a_header_and_one_row_per_sample) {
  const fs::path dir = fresh_folder("csv");
  const auto r = run(run_args + " --out " + (dir / "trajectory.csv").string());
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto rows = lines_of(slurp(dir / "trajectory.csv"));
  BOOST_TEST_REQUIRE(rows.size() == 4u);  // the header, t = 0, 300, 600
  const auto header = split(rows[0]);
  BOOST_TEST_REQUIRE(header.size() == 32u);  // t, r, v, Q1, Q2, omega1, omega2, energy
  BOOST_TEST(rows[0].rfind("t,r_x,r_y,r_z,v_x,v_y,v_z,Q1_11,Q1_12,Q1_13,Q1_21,", 0) == 0u, rows[0]);
  BOOST_TEST(rows[0].find(",omega2_z,energy") == rows[0].size() - 16, rows[0]);

  // the same numbers as the JSON lines
  const auto json = lines_of(run(run_args + " --json").out);
  BOOST_TEST_REQUIRE(json.size() == 4u);
  for (std::size_t i = 1; i < 4; ++i) {
    const auto sample = nlohmann::json::parse(json[i - 1]);
    const auto cells = split(rows[i]);
    BOOST_TEST_REQUIRE(cells.size() == 32u);
    BOOST_TEST(std::stod(cells[0]) == sample["t"].get<double>());
    BOOST_TEST(std::stod(cells[1]) == sample["r"][0].get<double>());
    BOOST_TEST(std::stod(cells[8]) == sample["Q1"][0][1].get<double>());
    BOOST_TEST(std::stod(cells[31]) == sample["energy"].get<double>());
  }
}

BOOST_AUTO_TEST_CASE(out_without_every_or_into_a_folder_is_refused_and_nothing_written) {
  const fs::path dir = fresh_folder("refused");
  expect_refusal("binary --system didymos --integrator KEPLER2 --h 60 --T 600 --out " + (dir / "t.jsonl").string(), "--every");
  expect_refusal(run_args + " --out " + dir.string(), "--out");
  expect_refusal(run_args + " --out " + (dir / "missing" / "t.jsonl").string(), "--out");
  BOOST_TEST(entries(dir).empty());
}

BOOST_AUTO_TEST_CASE(a_refused_run_leaves_an_existing_file_as_it_was) {
  const fs::path dir = fresh_folder("kept");
  { std::ofstream(dir / "t.jsonl") << "earlier\n"; }
  expect_refusal("binary --system didymos --integrator KEPLER2 --h 60 --T 610 --every 5 --out " + (dir / "t.jsonl").string(), "--T");  // not a whole number of steps
  BOOST_TEST(slurp(dir / "t.jsonl") == "earlier\n");
  BOOST_TEST(entries(dir) == std::set<std::string>{"t.jsonl"});
}

BOOST_AUTO_TEST_SUITE_END()
