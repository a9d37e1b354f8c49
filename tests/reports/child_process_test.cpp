// Helper programs run without a shell: arguments arrive verbatim, input and output of any size
// pass without deadlock, failures and time limits are reported, never a hang or a SIGPIPE.
#include <boost/test/unit_test.hpp>

#include <cerrno>
#include <chrono>
#include <cstdlib>

#include "folder_support.hpp"
#include "rotlie/reports/child_process.hpp"

BOOST_AUTO_TEST_SUITE(child_process_test)

namespace fs = std::filesystem;
using namespace report_test;
using rotlie::reports::run_child;
using namespace std::chrono_literals;

BOOST_AUTO_TEST_CASE(arguments_reach_the_program_verbatim) {
  const fs::path dir = scratch("child-args");
  const fs::path marker = dir / "MARKER";
  const std::string hostile = "`touch " + marker.string() + "`$(touch " + marker.string() + ");touch " +
                              marker.string() + "|'\"\n\\ *";
  const auto r = run_child({"printf", "%s", hostile}, "", 10s);
  BOOST_TEST(r.exit_status == 0);
  BOOST_TEST(r.out == hostile);
  BOOST_TEST(!fs::exists(marker));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(large_input_and_output_do_not_deadlock) {
  std::string input(4'000'000, ' ');
  for (std::size_t i = 0; i < input.size(); ++i) input[i] = static_cast<char>('a' + i % 26);
  const auto r = run_child({"cat"}, input, 60s);
  BOOST_TEST(r.exit_status == 0);
  BOOST_TEST((r.out == input));
}

BOOST_AUTO_TEST_CASE(exit_status_and_stderr_are_reported) {
  const auto r = run_child({"sh", "-c", "echo complaint >&2; exit 7"}, "", 10s);
  BOOST_TEST(r.exit_status == 7);
  BOOST_TEST(r.err == "complaint\n");
  BOOST_TEST(r.signal == 0);
}

BOOST_AUTO_TEST_CASE(a_child_that_stops_reading_is_no_sigpipe) {
  const auto r = run_child({"true"}, std::string(8'000'000, 'x'), 10s);  // more than any pipe buffer
  BOOST_TEST(r.exit_status == 0);
}

BOOST_AUTO_TEST_CASE(a_missing_program_is_a_start_error) {
  // A PATH of one readable empty folder: ENOENT (an unreadable PATH entry would give EACCES).
  const fs::path empty = scratch("child-empty-path");
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", empty.c_str(), 1);
  int error = 0;
  try {
    run_child({"rotlie-no-such-program"}, "", 10s);
  } catch (const rotlie::reports::child_start_error& e) {
    error = e.error;
  }
  ::setenv("PATH", saved.c_str(), 1);
  BOOST_TEST(error == ENOENT);
  fs::remove_all(empty);
}

BOOST_AUTO_TEST_CASE(the_time_limit_kills_the_child_and_what_it_started) {
  const auto start = std::chrono::steady_clock::now();
  // The grandchild holds the output pipe open: killing the process group must end it too.
  const auto r = run_child({"sh", "-c", "sleep 30 & sleep 30"}, "", 1s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST(r.timed_out);
  BOOST_TEST(r.signal == SIGKILL);
  BOOST_TEST(seconds < 5.0, seconds << " s");
}

BOOST_AUTO_TEST_CASE(the_time_limit_holds_after_the_outputs_close) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_child({"sh", "-c", "exec >&- 2>&-; sleep 30"}, "", 1s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST(r.timed_out);
  BOOST_TEST(seconds < 5.0, seconds << " s");
}

BOOST_AUTO_TEST_SUITE_END()  // child_process_test
