// Output files are written whole or not at all.
#define BOOST_TEST_MODULE output_file
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "rotlie/reports/output_file.hpp"

namespace fs = std::filesystem;
using rotlie::reports::write_file_atomically;

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

BOOST_AUTO_TEST_CASE(writes_and_replaces_whole_files) {
  const fs::path dir = fs::temp_directory_path() / ("rotlie-output-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_file_atomically(dir / "a.txt", "first");
  BOOST_TEST(slurp(dir / "a.txt") == "first");
  write_file_atomically(dir / "a.txt", "second, longer");
  BOOST_TEST(slurp(dir / "a.txt") == "second, longer");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  BOOST_TEST(entries == 1u);  // no temporary file left behind
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_missing_folder_is_an_error_not_a_partial_file) {
  const fs::path target = fs::temp_directory_path() / "rotlie-no-such-folder" / "x" / "a.txt";
  BOOST_CHECK_THROW(write_file_atomically(target, "content"), std::runtime_error);
  BOOST_TEST(!fs::exists(target));
}
