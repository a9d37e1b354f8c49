// `rotlie report --quick`, every section: a complete folder (the 16 sections' headings in index.md,
// every file it links present), nothing half-written left, and an audit in which every claim was
// measured but those --quick skips. Minutes of CPU (liquid water and LAMMPS, the maps): labelled slow,
// run after the default report and in CI.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(report_quick_cli_test)

namespace fs = std::filesystem;
using namespace rotlie::test_cli;

BOOST_AUTO_TEST_CASE(every_section_writes_its_files_and_links_them) {
  const fs::path out = scratch() / "report";
  const auto r = run("report --quick --out " + out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const std::string index = slurp(out / "index.md");
  std::vector<std::string> headings;
  std::istringstream lines(index);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("## ", 0) == 0) headings.push_back(line.substr(3));
  BOOST_TEST(headings.size() == 17u);
  for (const std::string start : {"Lie algebra", "Remainder formulas", "Dedicated N", "Accuracy against cost", "Stability",
                                  "Exact free-body flow", "van Zon & Schofield", "Liquid water at 300 K", "In LAMMPS",
                                  "Comparison over all rigid bodies", "Do the maps tell the truth", "Beyond the paper: dedicated 6th",
                                  "Beyond the paper: two free", "Spin", "Binary asteroid", "Audit"})
    BOOST_TEST(std::count_if(headings.begin(), headings.end(), [&](const std::string& h) { return h.rfind(start, 0) == 0; }) == 1,
               start);
  BOOST_TEST(std::count(headings.begin(), headings.end(), "Liquid water") == 1);  // vZS section V.C, beside "Liquid water at 300 K"
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    BOOST_TEST(e.path().string().find(".tmp.") == std::string::npos, "left-over " << e.path());
    files += e.is_regular_file();
  }
  BOOST_TEST(files > 90u);  // 152 with the charts' PNG files
  // every relative link of the index names a file that is there
  const std::regex link(R"(\]\(([^)#:]+)\))");
  std::size_t links = 0;
  for (auto it = std::sregex_iterator(index.begin(), index.end(), link); it != std::sregex_iterator(); ++it, ++links)
    BOOST_TEST(fs::exists(out / (*it)[1].str()), (*it)[1].str());
  BOOST_TEST(links > 20u);
  BOOST_TEST(nlohmann::json::parse(slurp(out / "table1.json")).at("blocks").size() == 4u);
  // the audit: every claim measured, but the R and P counts and digits the dedicated section skips with --quick
  const auto audit = nlohmann::json::parse(slurp(out / "audit" / "audit.json")).at("rows");
  BOOST_TEST(audit.size() > 40u);
  for (const auto& row : audit)
    if (row.at("verdict") == "not_computed")
      BOOST_TEST(row.at("verdict_text").get<std::string>().find("with --quick") != std::string::npos, row.at("statement"));
}

BOOST_AUTO_TEST_SUITE_END()  // report_quick_cli_test
