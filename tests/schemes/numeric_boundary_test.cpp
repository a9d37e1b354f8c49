// DESIGN.md: the numeric side (schemes/, models/) never includes a GiNaC or CLN header; scheme
// tables are the only thing that crosses. This scans every source file of those folders.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

BOOST_AUTO_TEST_SUITE(numeric_boundary_test)

BOOST_AUTO_TEST_CASE(no_symbolic_headers_on_the_numeric_side) {
  namespace fs = std::filesystem;
  int files = 0;
  for (const char* folder : {"schemes", "models"})
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(ROTLIE_SOURCE_DIR) / folder)) {
      if (!entry.is_regular_file()) continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      while (std::getline(in, line)) {
        if (line.rfind("#include", 0) != 0) continue;
        for (const char* banned : {"ginac", "cln/", "rotlie/lie/", "rotlie/bch/", "rotlie/solver/"})
          BOOST_TEST(line.find(banned) == std::string::npos, entry.path().string() << ": " << line);
      }
    }
  BOOST_TEST(files >= 8);
}

BOOST_AUTO_TEST_SUITE_END()  // numeric_boundary_test
