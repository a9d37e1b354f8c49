// The main of a folder's test executable (tests/CMakeLists.txt): its test files are suites of it.
#define BOOST_TEST_MODULE rotlie_tests
#include <boost/test/unit_test.hpp>
