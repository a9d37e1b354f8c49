// The main of a folder's test executable (tests/CMakeLists.txt): its test files are suites of it.
// A run in which every check passed but a case could not run its subject exits with skip_exit_code
// (skip.hpp), which CTest reports as skipped.
#define BOOST_TEST_MODULE rotlie_tests
#define BOOST_TEST_NO_MAIN
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

int main(int argc, char* argv[]) {
  const int status = boost::unit_test::unit_test_main(&init_unit_test, argc, argv);
  return status == 0 && rotlie::test::skipped_cases() > 0 ? rotlie::test::skip_exit_code : status;
}
