// The report's output folder: one report at a time (a second is refused and changes nothing),
// unusable folders are refused before any work, stale temporaries of dead runs are removed.
#include <boost/test/unit_test.hpp>

#include <fstream>

#include "folder_support.hpp"
#include "rotlie/reports/report_folder.hpp"

BOOST_AUTO_TEST_SUITE(report_folder_test)

namespace fs = std::filesystem;
using namespace report_test;
using rotlie::reports::output_folder_busy;
using rotlie::reports::report_folder;
using rotlie::reports::unusable_output_folder;

BOOST_AUTO_TEST_CASE(one_report_at_a_time) {
  const fs::path dir = scratch("folder-lock");
  std::ofstream(dir / "table.md") << "from the first run";
  {
    const report_folder first(dir);
    // flock belongs to an open file description: a second open conflicts even in one process.
    try {
      const report_folder second(dir);
      BOOST_FAIL("the second report was let in");
    } catch (const output_folder_busy& e) {
      BOOST_TEST(std::string(e.what()) ==
                 "another rotlie report is writing into '" + dir.string() + "'; wait for it to finish or choose another --out");
    }
  }
  BOOST_CHECK_NO_THROW(report_folder again(dir));  // released with the first
  BOOST_TEST(entries(dir) == std::set<std::string>{"table.md"});  // no lock file, nothing else
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(the_folder_is_created_with_its_parents) {
  const fs::path root = scratch("folder-create");
  { const report_folder folder(root / "a" / "b"); }
  BOOST_TEST(fs::is_directory(root / "a" / "b"));
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(unusable_folders_are_refused) {
  const fs::path root = scratch("folder-unusable");
  std::ofstream(root / "plain") << "x";
  const std::vector<std::pair<fs::path, std::string>> cases{
      {"", "the output folder (--out) is empty"},
      {root / "plain", "cannot write the report into '" + (root / "plain").string() + "': it exists and is not a folder"},
      {root / "plain" / "sub", "cannot create the output folder '" + (root / "plain" / "sub").string() + "': Not a directory"},
      {"/proc", "cannot write the report into '/proc': cannot create a file in it: "}};
  for (const auto& [path, message] : cases) {
    BOOST_TEST_CONTEXT("folder '" << path.string() << "'") {
      try {
        const report_folder folder(path);
        BOOST_FAIL("accepted");
      } catch (const unusable_output_folder& e) {
        BOOST_TEST(std::string(e.what()).rfind(message, 0) == 0u, e.what());
      }
    }
  }
  BOOST_TEST(entries(root) == std::set<std::string>{"plain"});
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(stale_temporaries_go_at_the_start) {
  const fs::path dir = scratch("folder-stale");
  const std::string stale = ".rotlie-tmp-" + std::to_string(dead_pid()) + "-7";
  std::ofstream(dir / stale) << "half";
  std::ofstream(dir / "kept.md") << "whole";
  { const report_folder folder(dir); }
  BOOST_TEST(entries(dir) == std::set<std::string>{"kept.md"});
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()  // report_folder_test
