// `rotlie sweep` end to end: its lines are each run's `binary` JSON in the input's order, runs that
// cannot be made get a status line and the sweep goes on; two MPI ranks write the lines of one
// process (timing aside) and compute rank 0's input alone; a killed sweep resumes without loss or
// duplicates; another input's file, a line that is no result and a line nested too deep are refused
// on resume and left as they were; the results file is locked by whatever name; refused runs end the
// command with status 3 and are counted in its last line.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "cli_support.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
  out << R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100, "order": 17})" << "\n";
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

std::string mpirun_prefix() {
  const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
  const std::string no_leak_check = std::getenv("LSAN_OPTIONS") != nullptr ? "env LSAN_OPTIONS=detect_leaks=0 " : "";
  return no_leak_check + std::string(ROTLIE_MPIEXEC) + " --oversubscribe" + root;
}

std::string sweep_args(const fs::path& in, const fs::path& out, bool resume = false) {
  return "sweep --in " + in.string() + " --out " + out.string() + (resume ? " --resume" : "");
}

}  // namespace

BOOST_AUTO_TEST_CASE(each_line_is_its_runs_binary_json_in_order) {
  const auto d = sweep_dir("order");
  write_runs(d / "runs.jsonl", 4);
  const auto r = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "results.jsonl").string());
  BOOST_REQUIRE_MESSAGE(r.status == 3, r.err);  // two runs refused
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
  BOOST_TEST(lines[5]["error"].get<std::string>().find("--order must be at most 16") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(two_mpi_ranks_write_the_lines_of_one_process) {
  if (!mpi_available()) {
    rotlie::test::skip("rotlie is built without MPI or mpirun is missing (install libopenmpi-dev openmpi-bin)");
    return;
  }
  const auto d = sweep_dir("mpi");
  write_runs(d / "runs.jsonl", 9);
  const auto one = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "one.jsonl").string());
  BOOST_REQUIRE_MESSAGE(one.status == 3, one.err);
  const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
  const std::string no_leak_check = std::getenv("LSAN_OPTIONS") != nullptr ? "env LSAN_OPTIONS=detect_leaks=0 " : "";
  const auto two = run_command(no_leak_check + std::string(ROTLIE_MPIEXEC) + " -n 2 --oversubscribe" + root + " " + ROTLIE_BINARY + " sweep --in " +
                               (d / "runs.jsonl").string() + " --out " + (d / "two.jsonl").string());
  BOOST_REQUIRE_MESSAGE(two.status == 3, two.err);
  BOOST_TEST(two.out.find("by 2 processes") != std::string::npos, two.out);
  BOOST_TEST((result_lines(d / "one.jsonl") == result_lines(d / "two.jsonl")));
}

BOOST_AUTO_TEST_CASE(a_killed_sweep_resumes_without_loss_or_duplicates) {
  const auto d = sweep_dir("killed");
  write_runs(d / "runs.jsonl", 60);
  const auto whole = run("sweep --in " + (d / "runs.jsonl").string() + " --out " + (d / "whole.jsonl").string());
  BOOST_REQUIRE_MESSAGE(whole.status == 3, whole.err);
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
  BOOST_REQUIRE_MESSAGE(resumed.status == 3, resumed.err);
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

// Rank 0 alone reads --in: each rank started in its own folder, where `runs.jsonl` names another
// input of as many runs, still computes rank 0's runs (a worker reading --in again would mix the two
// inputs' results under one header).
BOOST_AUTO_TEST_CASE(mpi_workers_compute_rank0s_input) {
  if (!mpi_available()) {
    rotlie::test::skip("rotlie is built without MPI or mpirun is missing (install libopenmpi-dev openmpi-bin)");
    return;
  }
  const auto d = sweep_dir("mpi_input");
  fs::create_directories(d / "rank0");
  fs::create_directories(d / "rank1");
  write_runs(d / "rank0" / "runs.jsonl", 4);
  {
    std::ofstream other(d / "rank1" / "runs.jsonl");
    for (int k = 0; k < 6; ++k)
      other << nlohmann::json{{"system", "didymos"}, {"integrator", "SIER4"}, {"h", 60}, {"T", 3600}, {"separation", 1.4}}.dump() << "\n";
  }
  const auto one = run(sweep_args(d / "rank0" / "runs.jsonl", d / "one.jsonl"));
  BOOST_REQUIRE_MESSAGE(one.status == 3, one.err);
  const auto rank = [&](const char* folder) {
    return " -n 1 --wdir " + (d / folder).string() + " " + ROTLIE_BINARY + " " + sweep_args("runs.jsonl", d / "two.jsonl");
  };
  const auto two = run_command(mpirun_prefix() + rank("rank0") + " :" + rank("rank1"));
  BOOST_REQUIRE_MESSAGE(two.status == 3, two.err);
  BOOST_TEST(two.out.find("by 2 processes") != std::string::npos, two.out);
  BOOST_TEST((result_lines(d / "one.jsonl") == result_lines(d / "two.jsonl")));
}

// Nesting a recursive writer cannot survive is refused in one line naming the line, before anything
// runs; in a results file it makes --resume refuse the file.
BOOST_AUTO_TEST_CASE(a_deeply_nested_line_is_refused_in_one_line) {
  const auto d = sweep_dir("deep");
  // a state object (its text is the JSON library's writing of it) nesting 200,000 arrays
  const std::string deep = R"({"state":{"r":)" + std::string(200000, '[') + std::string(200000, ']') + "}}";
  { std::ofstream(d / "runs.jsonl") << R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100})" << "\n" << deep << "\n"; }
  const auto r = run(sweep_args(d / "runs.jsonl", d / "results.jsonl"));
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(r.err.find("line 2") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("nested") != std::string::npos, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(!fs::exists(d / "results.jsonl"));

  write_runs(d / "good.jsonl", 1);
  const auto whole = run(sweep_args(d / "good.jsonl", d / "results.jsonl"));
  BOOST_REQUIRE_MESSAGE(whole.status == 3, whole.err);
  const std::string text = slurp(d / "results.jsonl");
  const std::string forged = text.substr(0, text.find('\n') + 1) + R"({"index":0,"x":)" + std::string(60000, '[') + std::string(60000, ']') + "}\n";
  { std::ofstream(d / "results.jsonl", std::ios::binary | std::ios::trunc) << forged; }
  const auto resumed = run(sweep_args(d / "good.jsonl", d / "results.jsonl", true));
  BOOST_TEST(resumed.status == 2, resumed.err);
  BOOST_TEST(resumed.err.find("line 2") != std::string::npos, resumed.err);
  BOOST_TEST((slurp(d / "results.jsonl") == forged));
}

// A line that names its run but holds no result is not a run done: --resume refuses the file and
// leaves it as it is.
BOOST_AUTO_TEST_CASE(forged_result_lines_are_refused_on_resume) {
  const auto d = sweep_dir("forged");
  write_runs(d / "runs.jsonl", 1);
  const auto whole = run(sweep_args(d / "runs.jsonl", d / "whole.jsonl"));
  BOOST_REQUIRE_MESSAGE(whole.status == 3, whole.err);
  const std::string text = slurp(d / "whole.jsonl");
  const std::string header = text.substr(0, text.find('\n') + 1);
  const std::string first = text.substr(header.size(), text.find('\n', header.size()) + 1 - header.size());
  for (const std::string line : {R"({"index":0})", R"({"index":0,"status":"refused"})", R"({"index":0,"status":"done","error":"x"})",
                                 R"({"index":0,"status":"contact","error":"x"})", R"({"index":0,"t":7200})"}) {
    const fs::path file = d / "forged.jsonl";
    { std::ofstream(file, std::ios::binary | std::ios::trunc) << header << line << "\n"; }
    const auto r = run(sweep_args(d / "runs.jsonl", file, true));
    BOOST_TEST(r.status == 2, line << ": " << r.err);
    BOOST_TEST(r.err.find("line 2 holds no result of run 0") != std::string::npos, line << ": " << r.err);
    BOOST_TEST((slurp(file) == header + line + "\n"), line);
    // after a good line too
    { std::ofstream(file, std::ios::binary | std::ios::trunc) << header << first << line << "\n"; }
    BOOST_TEST(run(sweep_args(d / "runs.jsonl", file, true)).status == 2, line);
  }
  // the lines a sweep writes are results: a file cut after its first run resumes
  const fs::path file = d / "cut.jsonl";
  { std::ofstream(file, std::ios::binary | std::ios::trunc) << header << first; }
  const auto resumed = run(sweep_args(d / "runs.jsonl", file, true));
  BOOST_TEST(resumed.status == 3, resumed.err);
  BOOST_TEST((result_lines(file) == result_lines(d / "whole.jsonl")));
}

// One results file reached through two hard links in two folders: the second sweep is refused at
// once (it is in use), and the file is the first sweep's alone. Two files of one folder are not one.
BOOST_AUTO_TEST_CASE(a_results_file_is_locked_whatever_its_name) {
  const auto d = sweep_dir("links");
  fs::create_directories(d / "a");
  fs::create_directories(d / "b");
  {
    std::ofstream out(d / "long.jsonl");
    for (int k = 0; k < 200; ++k)
      out << nlohmann::json{{"system", "didymos"}, {"integrator", "SIER4"}, {"h", 60}, {"T", 864000}, {"separation", 1.2 + 0.001 * k}}.dump() << "\n";
  }
  { std::ofstream(d / "a" / "results.jsonl"); }  // an empty file: a --resume starts it
  fs::create_hard_link(d / "a" / "results.jsonl", d / "b" / "results.jsonl");
  background_run first(sweep_args(d / "long.jsonl", d / "a" / "results.jsonl", true));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  const auto lines_in = [](const fs::path& f) { const auto t = slurp(f); return std::count(t.begin(), t.end(), '\n'); };
  while (std::chrono::steady_clock::now() < deadline && lines_in(d / "a" / "results.jsonl") < 2)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  BOOST_REQUIRE(first.running());
  const auto second = run(sweep_args(d / "long.jsonl", d / "b" / "results.jsonl", true));
  BOOST_TEST(second.status == 1, second.err);
  BOOST_TEST(second.err.find("another rotlie run is using") != std::string::npos, second.err);
  write_runs(d / "short.jsonl", 1);
  const auto beside = run(sweep_args(d / "short.jsonl", d / "a" / "other.jsonl"));
  BOOST_TEST(beside.status == 3, beside.err);
  BOOST_REQUIRE(first.running());
  first.stop();
  // the lines written are the first sweep's, in order, once each
  const auto lines = result_lines(d / "b" / "results.jsonl");
  for (std::size_t k = 0; k < lines.size(); ++k) BOOST_TEST(lines[k]["index"].get<std::size_t>() == k);
}

// A sweep that completes with refused or failed runs ends with status 3 and counts them; one whose
// runs all computed ends with 0.
BOOST_AUTO_TEST_CASE(refused_runs_give_exit_status_3_and_are_counted) {
  const auto d = sweep_dir("counts");
  write_runs(d / "runs.jsonl", 2);
  const auto r = run(sweep_args(d / "runs.jsonl", d / "results.jsonl"));
  BOOST_TEST(r.status == 3, r.err);
  BOOST_TEST(r.out.find("sweep of 4 runs: 2 computed, 0 contact, 2 refused, 0 failed") != std::string::npos, r.out);
  // a resume counts the whole file: the refused runs done before the kill still count
  const std::string text = slurp(d / "results.jsonl");
  std::size_t end = 0;
  for (int k = 0; k < 5; ++k) end = text.find('\n', end) + 1;
  { std::ofstream(d / "results.jsonl", std::ios::binary | std::ios::trunc) << text.substr(0, end); }
  const auto resumed = run(sweep_args(d / "runs.jsonl", d / "results.jsonl", true));
  BOOST_TEST(resumed.status == 3, resumed.err);
  BOOST_TEST(resumed.out.find("sweep of 4 runs: 2 computed, 0 contact, 2 refused, 0 failed (0 run now") != std::string::npos, resumed.out);
  { std::ofstream(d / "good.jsonl") << R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100})" << "\n"; }
  const auto good = run(sweep_args(d / "good.jsonl", d / "good-results.jsonl"));
  BOOST_TEST(good.status == 0, good.err);
  BOOST_TEST(good.out.find("sweep of 1 runs: 1 computed, 0 contact, 0 refused, 0 failed") != std::string::npos, good.out);
}

BOOST_AUTO_TEST_SUITE_END()  // sweep_cli_test
