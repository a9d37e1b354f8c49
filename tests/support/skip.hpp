// A test case that cannot run its subject here (a program or a file it needs is missing) says so with
// rotlie::test::skip(why): the message is logged, and the test executable then exits with
// skip_exit_code unless a check failed, so that CTest reports the test as skipped (SKIP_RETURN_CODE),
// never as passed.
#pragma once

#include <boost/test/unit_test.hpp>

#include <atomic>
#include <string>

namespace rotlie::test {

inline constexpr int skip_exit_code = 77;

inline std::atomic<int>& skipped_cases() {
  static std::atomic<int> count{0};
  return count;
}

inline void skip(const std::string& why) {
  ++skipped_cases();
  BOOST_TEST_MESSAGE("SKIPPED: " << why);
}

}  // namespace rotlie::test
