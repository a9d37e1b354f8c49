// The one map run (runs/map_run.hpp): on one process every line in grid order, equal to the rows
// computed one by one; a file killed half-way and resumed ends byte for byte as an uninterrupted one,
// and the lines handed on are the file's; a second process whose rows arrive in reverse order still
// gives the grid's order. The run on real MPI ranks against one process is map_cli_test's.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/runs/map_run.hpp"

BOOST_AUTO_TEST_SUITE(map_run_test)

using namespace rotlie;
namespace fs = std::filesystem;

namespace {

constexpr int K = 5;

runs::map_plan n_plan() { return runs::plan_map("N", K, runs::map_method_asked(runs::family_to_map("N"), K, false, false)); }

fs::path scratch_folder() {
  const fs::path p = fs::temp_directory_path() / ("rotlie-map-run-" + std::to_string(::getpid()));
  fs::create_directories(p);
  return p;
}

std::string file_text(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(one_process_returns_every_line_equal_to_the_rows_computed_one_by_one) {
  const auto plan = n_plan();
  runs::single_process alone;
  std::vector<std::string> handed_on;
  runs::map_run_output out;
  out.line = [&](const std::string& line) { handed_on.push_back(line); };
  const auto r = runs::run_map_rank0(plan, alone, out);
  BOOST_TEST(r.computed == plan.bodies.size());
  BOOST_TEST(!r.neighbour_check);  // N continued: no check
  std::vector<std::string> rows(plan.bodies.size());
  for (std::size_t first = 0; first < plan.bodies.size(); first += K)
    for (auto& [k, line] : runs::map_row_lines(plan.bodies, first, K, plan.done, "N", plan.method)) rows[k] = line;
  BOOST_TEST(r.lines == rows, boost::test_tools::per_element());
  BOOST_TEST(handed_on == rows, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_file_killed_half_way_and_resumed_ends_as_an_uninterrupted_one) {
  const fs::path folder = scratch_folder();
  const auto plan = n_plan();
  const std::string method = runs::map_method_name(plan.method);
  runs::single_process alone;
  runs::map_run_output whole;
  whole.path = folder / "whole.jsonl";
  runs::run_map_rank0(plan, alone, whole);
  const std::string expected = file_text(whole.path);

  // the first 7 bodies and half of the 8th, as a kill leaves a file
  std::istringstream lines(expected);
  std::string text, line;
  for (int n = 0; n < 8 && std::getline(lines, line); ++n) text += line + "\n";  // the header and 7 bodies
  std::getline(lines, line);
  text += line.substr(0, line.size() / 2);
  const fs::path killed = folder / "killed.jsonl";
  std::ofstream(killed) << text;

  auto resumed = runs::resume_map_file(killed, "N", K, method, plan.bodies);
  BOOST_TEST(resumed.lines.size() == 7u);
  auto again = plan;
  again.done = resumed.done;
  std::vector<std::string> handed_on;
  runs::map_run_output rest;
  rest.path = killed;
  rest.existing = &resumed;
  rest.line = [&](const std::string& l) { handed_on.push_back(l); };
  const auto r = runs::run_map_rank0(again, alone, rest);
  BOOST_TEST(r.computed == plan.bodies.size() - 7);
  BOOST_TEST(file_text(killed) == expected);
  std::vector<std::string> file_lines;
  std::istringstream written(expected);
  std::getline(written, line);  // the header
  while (std::getline(written, line)) file_lines.push_back(line);
  BOOST_TEST(handed_on == file_lines, boost::test_tools::per_element());  // the 7 kept, then the rest
  fs::remove_all(folder);
}

// Rank 0 of two, the other process scripted: its rows (the odd ones) arrive at once, in reverse order.
class scripted_partner final : public runs::map_processes {
 public:
  explicit scripted_partner(std::vector<message> lines) : lines_(std::move(lines)) {}
  int rank() const override { return 0; }
  int size() const override { return 2; }
  std::string broadcast(const std::string& text) override { return text; }
  void send_results(const std::vector<std::pair<std::size_t, std::string>>&) override { throw std::logic_error("rank 0 sends nothing"); }
  void send_done() override {}
  delivery receive(bool) override {
    if (delivered_) return {};
    delivered_ = true;
    return {std::vector<message>(lines_.rbegin(), lines_.rend()), 1};
  }

 private:
  std::vector<message> lines_;
  bool delivered_ = false;
};

BOOST_AUTO_TEST_CASE(rows_of_another_process_arriving_out_of_order_come_out_in_grid_order) {
  const auto plan = n_plan();
  std::vector<std::string> rows(plan.bodies.size());
  std::vector<runs::map_processes::message> partners;
  for (std::size_t first = 0, row = 0; first < plan.bodies.size(); first += K, ++row)
    for (auto& [k, line] : runs::map_row_lines(plan.bodies, first, K, plan.done, "N", plan.method)) {
      rows[k] = line;
      if (row % 2 == 1) partners.push_back({k, line});
    }
  scripted_partner two(partners);
  std::vector<std::string> handed_on;
  runs::map_run_output out;
  out.line = [&](const std::string& line) { handed_on.push_back(line); };
  const auto r = runs::run_map_rank0(plan, two, out);
  BOOST_TEST(r.lines == rows, boost::test_tools::per_element());
  BOOST_TEST(handed_on == rows, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_resume_that_is_not_the_plans_is_refused) {
  auto plan = n_plan();
  runs::single_process alone;
  runs::resumed_map existing;
  existing.done.assign(plan.bodies.size(), 1);
  runs::map_run_output out;
  out.path = scratch_folder() / "never.jsonl";
  out.existing = &existing;  // the plan's done marks are all 0
  BOOST_CHECK_THROW(runs::run_map_rank0(plan, alone, out), std::invalid_argument);
  BOOST_TEST(!fs::exists(out.path));
}

BOOST_AUTO_TEST_CASE(one_process_has_nobody_to_send_to) {
  runs::single_process alone;
  BOOST_CHECK_THROW(alone.send_results({{0, "x"}}), std::logic_error);
  BOOST_TEST(alone.broadcast("text") == "text");
}

BOOST_AUTO_TEST_SUITE_END()  // map_run_test
