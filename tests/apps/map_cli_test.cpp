// rotlie map and rotlie best end to end: the map's best N equals `solve`'s at grid bodies (one near
// the spherical top) and `best`'s equals it at water; a killed and resumed map is the uninterrupted
// file byte for byte; a file of another grid or family is refused and left as it was; two MPI
// ranks write the file of one process.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "cli_support.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

BOOST_AUTO_TEST_SUITE(map_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

std::vector<nlohmann::json> body_lines(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<nlohmann::json> out;
  std::getline(in, line);  // header
  while (std::getline(in, line)) out.push_back(nlohmann::json::parse(line));
  return out;
}

std::string solution_name(const nlohmann::json& s) {
  return s.at("scheme").get<std::string>() + ":" + s.at("perm").get<std::string>() + ":" + std::to_string(s.at("label").get<int>());
}

// The uninterrupted N map at K = 8 (56 asymmetric bodies), computed once.
const fs::path& reference_map() {
  static const fs::path dir = [] {
    const fs::path d = scratch() / "uninterrupted";
    const auto r = run("map --family N --grid 8 --out " + d.string());
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
    return d;
  }();
  return dir;
}

}  // namespace

BOOST_AUTO_TEST_CASE(map_best_equals_solve_best_near_the_spherical_top_and_elsewhere) {
  const auto lines = body_lines(reference_map() / "map-N.jsonl");
  BOOST_REQUIRE_EQUAL(lines.size(), 7u * 8u);
  // The body next to the spherical top (s = t = 7/8), a flat one (t = 0) and one inside.
  for (const auto& [s, t] : std::vector<std::pair<std::string, std::string>>{{"7/8", "7/8"}, {"1/2", "0"}, {"3/8", "5/8"}}) {
    const auto found = std::find_if(lines.begin(), lines.end(), [&](const auto& l) { return l.at("s") == s && l.at("t") == t; });
    BOOST_REQUIRE(found != lines.end());
    const auto& I = found->at("I");
    const std::string inertia = I[0].get<std::string>() + "," + I[1].get<std::string>() + "," + I[2].get<std::string>();
    const auto solved = run("solve --family N --inertia " + inertia + " --json");
    BOOST_REQUIRE_MESSAGE(solved.status == 0, solved.err);
    const auto j = nlohmann::json::parse(solved.out);
    BOOST_TEST_CONTEXT("body " << inertia) {
      BOOST_TEST(found->at("best").get<std::string>() == solution_name(j.at("solutions").at(0)));
      // The default map carries solutions by continuation and evaluates ‖H_R5‖ on the interpolated
      // conditions, `solve` by the BCH at the exact solution: the same number to rounding.
      BOOST_TEST(found->at("remainder").get<double>() == j.at("solutions").at(0).at("analytic_remainder").get<double>(),
                 boost::test_tools::tolerance(1e-12));
      BOOST_TEST(found->at("reference").get<std::string>().rfind("RS4-S5-McLachlan:", 0) == 0u);
    }
    // The name is one that integrate accepts for that body.
    const auto integrated = run("integrate --scheme " + found->at("best").get<std::string>() + " --inertia " + inertia +
                                " --h 1/8 --json");
    BOOST_TEST(integrated.status == 0, integrated.err);
  }
}

// best's N and R are solve's first solutions. On the body (1, 3, 4), whose P systems (which best solves
// too) take a third of water's time; at water, solve's first N is Table 4's least remainder, N2:BAC:2.
BOOST_AUTO_TEST_CASE(best_equals_solve) {
  const auto best = run("best --inertia 1,3,4 --json");
  BOOST_REQUIRE_MESSAGE(best.status == 0, best.err);
  const auto b = nlohmann::json::parse(best.out);
  for (const char* family : {"N", "R"}) {
    const auto solved = run(std::string("solve --family ") + family + " --inertia 1,3,4 --json");
    BOOST_REQUIRE(solved.status == 0);
    BOOST_TEST(b.at(family).at("best").get<std::string>() == solution_name(nlohmann::json::parse(solved.out).at("solutions").at(0)));
  }
  const auto water = run("solve --family N --inertia water --json");
  BOOST_REQUIRE(water.status == 0);
  BOOST_TEST(solution_name(nlohmann::json::parse(water.out).at("solutions").at(0)) == "N2:BAC:2");
  BOOST_TEST(b.at("reference").at("best").get<std::string>().rfind("RS4-S5-McLachlan:", 0) == 0u);
  const double gain = b.at("N").at("gain").get<double>();
  BOOST_TEST(gain == b.at("reference").at("remainder").get<double>() / b.at("N").at("remainder").get<double>() *
                         std::pow(12.0 / 9.0, 4),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_killed_and_resumed_map_is_the_uninterrupted_file) {
  const std::string expected = slurp(reference_map() / "map-N.jsonl");
  const fs::path dir = scratch() / "killed", file = dir / "map-N.jsonl";
  const pid_t child = ::fork();
  if (child == 0) {
    ::freopen("/dev/null", "w", stdout);
    ::execl(ROTLIE_BINARY, ROTLIE_BINARY, "map", "--family", "N", "--grid", "8", "--out", dir.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Kill it after a few lines, mid-run.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string now = slurp(file);
    if (std::count(now.begin(), now.end(), '\n') >= 5) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::string partial = slurp(file);
  BOOST_TEST_MESSAGE("killed after " << std::count(partial.begin(), partial.end(), '\n') << " lines");
  BOOST_REQUIRE(partial.size() < expected.size());
  BOOST_REQUIRE(expected.compare(0, partial.size(), partial) == 0);
  // A torn last line, as a write cut by the kill would leave: dropped on resume.
  { std::ofstream(file, std::ios::binary | std::ios::trunc) << partial.substr(0, partial.size() - 40); }
  const auto resumed = run("map --family N --grid 8 --out " + dir.string() + " --resume");
  BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
  BOOST_TEST((slurp(file) == expected));
  // Resuming a finished map computes nothing and changes nothing.
  const auto again = run("map --family N --grid 8 --out " + dir.string() + " --resume");
  BOOST_TEST(again.status == 0);
  BOOST_TEST((slurp(file) == expected));
}

BOOST_AUTO_TEST_CASE(bytes_no_kill_could_leave_after_the_last_line_are_refused_and_kept) {
  // A kill leaves at most the start of one JSON line; binary data (or no header at all) was once
  // taken for a torn line and overwritten by a fresh map.
  const std::string whole = slurp(reference_map() / "map-N.jsonl");
  const std::string header = whole.substr(0, whole.find('\n') + 1);
  const fs::path dir = scratch() / "garbage", file = dir / "map-N.jsonl";
  fs::create_directories(dir);
  for (const std::string& text : {std::string("\x00\xff\x01garbage", 10), header + std::string("\x00\xff\x01", 3),
                                  header + "not a map line"}) {
    { std::ofstream(file, std::ios::binary | std::ios::trunc) << text; }
    const auto r = run("map --family N --grid 8 --resume --out " + dir.string());
    BOOST_TEST(r.status == 2, r.err);
    BOOST_TEST(r.err.find("not the start of a map line") != std::string::npos, r.err);
    BOOST_TEST((slurp(file) == text));
  }
}

BOOST_AUTO_TEST_CASE(a_file_of_another_grid_or_family_is_refused_and_left_as_it_is) {
  const std::string expected = slurp(reference_map() / "map-N.jsonl");
  const fs::path dir = scratch() / "other";
  fs::create_directories(dir);
  fs::copy_file(reference_map() / "map-N.jsonl", dir / "map-N.jsonl", fs::copy_options::overwrite_existing);
  fs::copy_file(reference_map() / "map-N.jsonl", dir / "map-R.jsonl", fs::copy_options::overwrite_existing);
  for (const auto& args : {"map --family N --grid 9 --resume --out ", "map --family R --grid 8 --resume --out ",
                           "map --family N --grid 8 --out ", "map --family N --grid 8 --exact --resume --out ",
                           "map --family R --grid 2 --fast --out "}) {
    const auto r = run(args + dir.string());
    BOOST_TEST_CONTEXT(args) {
      BOOST_TEST(r.status == 2);
      BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
  }
  BOOST_TEST((slurp(dir / "map-N.jsonl") == expected));
  BOOST_TEST((slurp(dir / "map-R.jsonl") == expected));
}

// --json without --out: no file, nothing to resume; the lines printed are the file's body lines.
BOOST_AUTO_TEST_CASE(json_alone_prints_the_lines_of_the_file) {
  const auto r = run("map --family N --grid 8 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const std::string file = slurp(reference_map() / "map-N.jsonl");
  BOOST_TEST(r.out == file.substr(file.find('\n') + 1));  // after the header
}

// The default map (continuation, confirmed by the exact solver) and `--exact` (the exact solver at
// every body) agree body for body on every best integrator, permutation and label.
BOOST_AUTO_TEST_CASE(the_exact_map_has_the_same_best_integrators) {
  const fs::path dir = scratch() / "exact";
  fs::remove_all(dir);
  const auto r = run("map --family N --grid 8 --exact --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto exact = body_lines(dir / "map-N.jsonl"), fast = body_lines(reference_map() / "map-N.jsonl");
  BOOST_REQUIRE_EQUAL(exact.size(), fast.size());
  for (std::size_t k = 0; k < exact.size(); ++k) {
    BOOST_TEST_CONTEXT("s = " << exact[k].at("s") << ", t = " << exact[k].at("t")) {
      BOOST_TEST(exact[k].at("best") == fast[k].at("best"));
      BOOST_TEST(exact[k].at("reference") == fast[k].at("reference"));
      BOOST_TEST(exact[k].at("real_solutions") == fast[k].at("real_solutions"));
      for (std::size_t p = 0; p < 6; ++p) BOOST_TEST(exact[k].at("permutations")[p].at("best") == fast[k].at("permutations")[p].at("best"));
    }
  }
}

bool mpi_available() {
  if (!ROTLIE_MAP_MPI) return false;
  return std::string(ROTLIE_MPIEXEC).size() > 0 && fs::exists(ROTLIE_MPIEXEC);
}

BOOST_AUTO_TEST_CASE(two_mpi_ranks_write_the_file_of_one_process) {
  if (!mpi_available()) {
    rotlie::test::skip("rotlie is built without MPI or mpirun is missing (install libopenmpi-dev openmpi-bin)");
    return;
  }
  const fs::path dir = scratch() / "mpi";
  // As root, Open MPI refuses to start without its explicit consent.
  const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
  // Under the sanitizers (LSAN_OPTIONS set by the sanitize test preset) the ranks run without the leak
  // check: Open MPI leaks from components it dlopens and closes again, whose frames have no module left
  // to suppress by. The one-process reference map above keeps the leak check on rotlie's own code.
  const std::string no_leak_check = std::getenv("LSAN_OPTIONS") != nullptr ? "env LSAN_OPTIONS=detect_leaks=0 " : "";
  const auto r = run_command(no_leak_check + std::string(ROTLIE_MPIEXEC) + " -n 2 --oversubscribe" + root + " " + ROTLIE_BINARY +
                             " map --family N --grid 8 --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  BOOST_TEST(r.out.find("by 2 processes") != std::string::npos, r.out);
  BOOST_TEST((slurp(dir / "map-N.jsonl") == slurp(reference_map() / "map-N.jsonl")));
}

BOOST_AUTO_TEST_SUITE_END()  // map_cli_test
