// `rotlie report --quick`, every section: a complete folder (each section's heading in index.md, the
// files it lists present), nothing half-written left, and an audit whose rows all ran. Minutes of
// CPU (liquid water and LAMMPS, the maps): labelled slow, run after the default report and in CI.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

BOOST_AUTO_TEST_SUITE(report_quick_cli_test)

namespace fs = std::filesystem;
using namespace rotlie::test_cli;

BOOST_AUTO_TEST_CASE(every_section_writes_its_files_and_links_them) {
  const fs::path out = scratch() / "report";
  const auto r = run("report --quick --out " + out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const std::string index = slurp(out / "index.md");
  for (const auto* heading : {"Table 1", "Accuracy against cost", "van Zon & Schofield", "Liquid water",
                              "Comparison over all rigid bodies", "Beyond the paper", "Spin", "Audit"})
    BOOST_TEST(index.find(heading) != std::string::npos, heading);
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    BOOST_TEST(e.path().string().find(".tmp.") == std::string::npos, "left-over " << e.path());
    files += e.is_regular_file();
  }
  BOOST_TEST(files > 100u);
  // every relative link of the index names a file that is there
  const std::regex link(R"(\]\(([^)#:]+)\))");
  std::size_t links = 0;
  for (auto it = std::sregex_iterator(index.begin(), index.end(), link); it != std::sregex_iterator(); ++it, ++links)
    BOOST_TEST(fs::exists(out / (*it)[1].str()), (*it)[1].str());
  BOOST_TEST(links > 20u);
  BOOST_TEST(nlohmann::json::parse(slurp(out / "table1.json")).at("blocks").size() == 4u);
}

BOOST_AUTO_TEST_SUITE_END()  // report_quick_cli_test
