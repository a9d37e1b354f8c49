// `rotlie sweep` end to end: its lines are each run's `binary` JSON in the input's order, runs that
// cannot be made get a status line and the sweep goes on; two MPI ranks write the lines of one
// process (timing aside); a killed sweep resumes without loss or duplicates; another input's file is
// refused on resume and left as it was.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "cli_support.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

BOOST_AUTO_TEST_SUITE(sweep_cli_test)

using namespace rotlie::test_cli;

namespace {

fs::path sweep_dir(const std::string& name) {
  const auto d = fs::temp_directory_path() / ("rotlie-sweep-" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// n runs of the Didymos system at separations 1.2, 1.21, … km over two hours, and two that cannot run
void write_runs(const fs::path& file, int n) {
  std::ofstream out(file);
  for (int k = 0; k < n; ++k)
    out << nlohmann::json{{"system", "didymos"}, {"integrator", k % 2 ? "KEPLER4" : "SIER4"}, {"h", 120}, {"T", 7200}, {"separation", 1.2 + 0.01 * k}}.dump()
        << "\n";
  out << R"({"system": "didymos", "integrator": "NOPE", "h": 10, "T": 100})" << "\n";
  out << R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100, "order": 3})" << "\n";
}

// The result lines with the timing left out.
std::vector<nlohmann::json> result_lines(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<nlohmann::json> out;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    auto j = nlohmann::json::parse(line);
    j.erase("cpu_s");  // the measured values, not computed ones
    if (j.contains("error_estimate") && j["error_estimate"].is_object()) j["error_estimate"].erase("cpu_s");
    out.push_back(j);
  }
  return out;
}

bool mpi_available() { return ROTLIE_MAP_MPI && std::string(ROTLIE_MPIEXEC).size() > 0 && fs::exists(ROTLIE_MPIEXEC); }

}  // namespace

BOOST_AUTO_TEST_CASE(each_line_is_its_runs_binary_json_in_order) {
  const auto d = sweep_dir("order");
  write_runs(d / "runs.jsonl", 4);
  const auto r = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "results.jsonl").string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto lines = result_lines(d / "results.jsonl");
  BOOST_TEST_REQUIRE(lines.size() == 6u);
  for (std::size_t k = 0; k < lines.size(); ++k) BOOST_TEST(lines[k]["index"].get<std::size_t>() == k);
  // the third run by hand: the same JSON
  const auto alone = run("binary --system didymos --integrator SIER4 --h 120 --T 7200 --separation 1.22 --json");
  BOOST_REQUIRE(alone.status == 0);
  auto j = nlohmann::json::parse(alone.out);
  j.erase("cpu_s");
  j["error_estimate"].erase("cpu_s");
  j["index"] = 2;
  BOOST_TEST(lines[2] == j);
  BOOST_TEST(lines[4]["status"] == "refused");
  BOOST_TEST(lines[4]["error"].get<std::string>().find("unknown integrator 'NOPE'") != std::string::npos);
  BOOST_TEST(lines[5]["error"].get<std::string>().find("--order must be 0, 2 or 4") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(two_mpi_ranks_write_the_lines_of_one_process) {
  if (!mpi_available()) {
    rotlie::test::skip("rotlie is built without MPI or mpirun is missing (install libopenmpi-dev openmpi-bin)");
    return;
  }
  const auto d = sweep_dir("mpi");
  write_runs(d / "runs.jsonl", 9);
  const auto one = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "one.jsonl").string());
  BOOST_REQUIRE_MESSAGE(one.status == 0, one.err);
  const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
  const std::string no_leak_check = std::getenv("LSAN_OPTIONS") != nullptr ? "env LSAN_OPTIONS=detect_leaks=0 " : "";
  const auto two = run_command(no_leak_check + std::string(ROTLIE_MPIEXEC) + " -n 2 --oversubscribe" + root + " " + ROTLIE_BINARY + " sweep --in " +
                               (d / "runs.jsonl").string() + " --out " + (d / "two.jsonl").string());
  BOOST_REQUIRE_MESSAGE(two.status == 0, two.err);
  BOOST_TEST(two.out.find("by 2 processes") != std::string::npos, two.out);
  BOOST_TEST((result_lines(d / "one.jsonl") == result_lines(d / "two.jsonl")));
}

BOOST_AUTO_TEST_CASE(a_killed_sweep_resumes_without_loss_or_duplicates) {
  const auto d = sweep_dir("killed");
  write_runs(d / "runs.jsonl", 60);
  const auto whole = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "whole.jsonl").string());
  BOOST_REQUIRE_MESSAGE(whole.status == 0, whole.err);
  const fs::path file = d / "killed.jsonl";
  const pid_t child = ::fork();
  if (child == 0) {
    ::freopen("/dev/null", "w", stdout);
    const std::string in = (d / "runs.jsonl").string(), out = file.string();
    ::execl(ROTLIE_BINARY, ROTLIE_BINARY, "sweep", "--in", in.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string now = slurp(file);
    if (std::count(now.begin(), now.end(), '\n') >= 6) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  const std::string partial = slurp(file);
  const auto lines_then = std::count(partial.begin(), partial.end(), '\n');
  BOOST_TEST_MESSAGE("killed after " << lines_then << " lines");
  BOOST_REQUIRE(lines_then < 63);
  // a torn last line, as a write cut by the kill would leave: dropped on resume
  { std::ofstream(file, std::ios::binary | std::ios::app) << R"({"index":)"; }
  const auto resumed = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + file.string() + " --resume");
  BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
  BOOST_TEST((result_lines(file) == result_lines(d / "whole.jsonl")));
  // without --resume an existing file is refused; another input's file is refused on resume; both left as they are
  const auto before = slurp(file);
  BOOST_TEST(run("sweep --in " + (d / "runs.jsonl").string() + " --out " + file.string()).status == 2);
  write_runs(d / "other.jsonl", 3);
  const auto other = run("sweep --in " + (d / "other.jsonl").string() + " --out " + file.string() + " --resume");
  BOOST_TEST(other.status == 2);
  BOOST_TEST(other.err.find("another input file") != std::string::npos, other.err);
  BOOST_TEST((slurp(file) == before));
}

BOOST_AUTO_TEST_CASE(a_line_that_is_not_binarys_options_is_refused_before_anything_runs) {
  const auto d = sweep_dir("bad");
  { std::ofstream(d / "runs.jsonl") << R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100})" << "\n" << R"({"every": 3})" << "\n"; }
  const auto r = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "results.jsonl").string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("line 2: 'every' is not an option of binary") != std::string::npos, r.err);
  BOOST_TEST(!fs::exists(d / "results.jsonl"));
}

BOOST_AUTO_TEST_SUITE_END()  // sweep_cli_test
