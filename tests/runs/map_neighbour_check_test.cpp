// The neighbour check of a screened map (runs/map_neighbour_check.hpp): a body whose line names a
// best that a neighbour's best system beats there is replaced by the exact solver's line, and an
// exact map is left as it is. The shipped P map's own case at --grid 200 is in shipped_maps_test.
#include <boost/test/unit_test.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/solver/body_grid.hpp"

using namespace rotlie;

namespace {

// The exact N map at --grid 10 (N's exact solver is cheap), computed once for every case.
const std::vector<std::string>& exact_n_map() {
  static const std::vector<std::string> lines = [] {
    std::vector<std::string> out;
    for (const auto& g : solver::asymmetric_grid(10)) out.push_back(runs::exact_map_line(g, "N"));
    return out;
  }();
  return lines;
}

std::string system_of(const nlohmann::json& line) {
  const std::string label = line.at("best").get<std::string>();
  return label.substr(0, label.rfind(':'));
}

// The first body whose right-hand neighbour in its row shares its best system, with a line that
// names instead another permutation's best, more than twice worse; nullopt when there is none.
std::optional<std::pair<std::size_t, std::string>> worse_best_beside_the_right_one(const std::vector<solver::grid_body>& bodies,
                                                                                    const std::vector<std::string>& exact) {
  for (std::size_t k = 0; k + 1 < bodies.size(); ++k) {
    const auto line = nlohmann::json::parse(exact[k]), next = nlohmann::json::parse(exact[k + 1]);
    if (bodies[k + 1].i != bodies[k].i || !line["best"].is_string() || !next["best"].is_string() || system_of(line) != system_of(next))
      continue;
    for (const auto& p : line["permutations"])
      if (p["best"].is_string() && p["remainder"].get<double>() > 2 * line["remainder"].get<double>()) {
        auto worse = line;
        worse["best"] = p["best"];
        worse["remainder"] = p["remainder"];
        return std::pair(k, worse.dump());
      }
  }
  return std::nullopt;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(map_neighbour_check_test)

BOOST_AUTO_TEST_CASE(tasks_survive_their_text) {
  const std::vector<runs::neighbour_task> tasks = {{12, "P8", "ABC"}, {7, "", ""}, {0, "N3", "BAC"}};
  const auto back = runs::tasks_from_text(runs::tasks_text(tasks));
  BOOST_TEST_REQUIRE(back.size() == tasks.size());
  for (std::size_t n = 0; n < tasks.size(); ++n) {
    BOOST_TEST(back[n].body == tasks[n].body);
    BOOST_TEST(back[n].scheme == tasks[n].scheme);
    BOOST_TEST(back[n].permutation == tasks[n].permutation);
  }
  BOOST_CHECK_THROW(runs::tasks_from_text("x P8 ABC\n"), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(an_exact_map_is_left_alone_and_a_worse_best_is_replaced) {
  const auto bodies = solver::asymmetric_grid(10);
  const auto& exact = exact_n_map();
  auto lines = exact;
  const auto run = runs::local_neighbour_runner(bodies, "N");
  const auto untouched = runs::check_neighbours(bodies, lines, run);
  BOOST_TEST(untouched.replaced == 0u);
  BOOST_TEST(untouched.probes > 0u);
  BOOST_TEST(lines == exact);

  // A body inside a region of one best: its line is made to name another permutation's best, worse
  const auto worse = worse_best_beside_the_right_one(bodies, exact);
  BOOST_TEST_REQUIRE(worse.has_value());
  lines = exact;
  lines[worse->first] = worse->second;
  const auto repaired = runs::check_neighbours(bodies, lines, run);
  BOOST_TEST(repaired.replaced == 1u);
  BOOST_TEST(lines == exact);  // the exact solver's line again, byte for byte
}

BOOST_AUTO_TEST_CASE(a_system_the_solver_refuses_shows_nothing_and_the_lines_stay) {
  const auto bodies = solver::asymmetric_grid(10);
  auto lines = exact_n_map();
  auto odd = nlohmann::json::parse(lines[3]);
  odd["best"] = "N99:ABC:1";  // no such scheme: its neighbours' probes of it throw
  lines[3] = odd.dump();
  const auto expected = lines;
  const auto c = runs::check_neighbours(bodies, lines, runs::local_neighbour_runner(bodies, "N"));
  BOOST_TEST(c.failed_probes > 0u);
  BOOST_TEST(c.replaced == 0u);
  BOOST_TEST(lines == expected);
  odd["best"] = "N2";  // not SCHEME:PERM:LABEL: not a system to probe
  lines[3] = odd.dump();
  BOOST_TEST(runs::check_neighbours(bodies, lines, runs::local_neighbour_runner(bodies, "N")).failed_probes == 0u);
}

BOOST_AUTO_TEST_CASE(a_map_file_is_checked_once_and_rewritten_whole) {
  const auto bodies = solver::asymmetric_grid(10);
  const auto& exact = exact_n_map();
  const auto worse = worse_best_beside_the_right_one(bodies, exact);
  BOOST_TEST_REQUIRE(worse.has_value());
  const auto dir = std::filesystem::temp_directory_path() / ("rotlie-neighbour-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "map-N.jsonl";

  const auto read = [&] {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  auto header = runs::map_header("N", 10, bodies.size(), "exact");
  header["neighbour_check"] = nullptr;  // not a record of a check: checked
  {
    std::ofstream out(file);
    out << header.dump() << "\n";
    for (std::size_t k = 0; k < exact.size(); ++k) out << (k == worse->first ? worse->second : exact[k]) << "\n";
  }
  const auto run = runs::local_neighbour_runner(bodies, "N");
  const auto c = runs::check_map_file(file, 10, bodies, run);
  BOOST_TEST_REQUIRE(c.has_value());
  BOOST_TEST(c->replaced == 1u);
  const std::string after = read();
  const auto first = nlohmann::json::parse(after.substr(0, after.find('\n')));
  const auto recorded = runs::recorded_neighbour_check(first);
  BOOST_TEST_REQUIRE(recorded.has_value());
  BOOST_TEST(recorded->replaced == 1u);
  BOOST_TEST(recorded->probes == c->probes);
  std::string body_lines;
  for (const auto& l : exact) body_lines += l + "\n";
  BOOST_TEST(after.substr(after.find('\n') + 1) == body_lines);  // every body line the exact solver's, in grid order
  BOOST_TEST(!runs::check_map_file(file, 10, bodies, run).has_value());  // recorded: not checked again
  BOOST_TEST(read() == after);
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()  // map_neighbour_check_test
