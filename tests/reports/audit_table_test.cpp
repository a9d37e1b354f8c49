// The audit table builder on synthetic report folders: verdicts follow the numbers in the files
// (they flip when a value crosses its tolerance), a missing file or a section that did not run
// gives "not computed", never a number; and the audit section's own cost.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <ctime>
#include <fstream>
#include <tuple>

#include "folder_support.hpp"
#include "rotlie/reports/audit_claim.hpp"
#include "rotlie/reports/audit_table.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/report_csv_reader.hpp"

BOOST_AUTO_TEST_SUITE(audit_table_test)

namespace fs = std::filesystem;
using namespace rotlie::reports;

namespace {

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// A chart CSV whose curves are error = K (h/C)^4 exactly, at h/C = 2^-i / 9.
std::string fourth_order_curves(const std::vector<std::pair<std::string, double>>& constants) {
  std::ostringstream o;
  o.precision(17);
  o << "series,x,y\n";
  for (const auto& [name, K] : constants)
    for (int i = 1; i <= 6; ++i) {
      const double x = std::ldexp(1.0, -i) / 9;
      o << '"' << name << "\"," << x << "," << K * std::pow(x, 4) << "\n";
    }
  return o.str();
}

const audit_row& find_row(const std::vector<audit_row>& rows, const std::string& start) {
  for (const auto& r : rows)
    if (r.statement.rfind(start, 0) == 0) return r;
  BOOST_FAIL("no row starting with " + start);
  throw;
}

// Four bodies away from the tops and one near them; `wins` of the five beat the reference.
std::string map_file(const std::string& family, const std::vector<double>& ratios) {
  const std::vector<std::pair<std::string, std::string>> bodies = {
      {"1/3", "2/3"}, {"7/20", "13/20"}, {"3/10", "7/10"}, {"1/3", "7/10"}, {"3/10", "49/50"}};
  std::string out = "{\"rotlie_map\":1,\"family\":\"" + family + "\",\"grid\":40}\n";
  for (std::size_t k = 0; k < ratios.size(); ++k)
    out += "{\"s\":\"0\",\"t\":\"" + std::to_string(k) + "/40\",\"I\":[\"" + bodies[k].first + "\",\"" + bodies[k].second +
           "\",\"1\"],\"family\":\"" + family + "\",\"best\":\"" + family + "1:ABC:1\",\"ratio\":" + std::to_string(ratios[k]) +
           ",\"singular\":[]}\n";
  return out;
}

audit_inputs all_sections(const fs::path& dir) {
  audit_inputs in;
  in.folder = dir;
  in.sections_run = {"dedicated", "accuracy", "maps", "maps-truth"};
  return in;
}

}  // namespace

BOOST_AUTO_TEST_CASE(rank_correlation_matches_the_closed_form) {
  // One swapped pair among five: rho = 1 - 6 * 2 / (5 * 24) = 0.9.
  BOOST_TEST(rank_correlation({1, 2, 3, 4, 5}, {10, 20, 30, 50, 40}) == 0.9, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(rank_correlation({1, 2, 3}, {3, 2, 1}) == -1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::isnan(rank_correlation({1, 2}, {1, 2})));
}

BOOST_AUTO_TEST_CASE(csv_reader_reads_quoted_fields) {
  const auto dir = report_test::scratch("audit-csv");
  write(dir / "t.csv", "a,b\n\"x, \"\"y\"\"\",2\n");
  const auto t = read_csv(dir / "t.csv");
  BOOST_REQUIRE(t);
  BOOST_TEST(t->rows.at(0).at(0) == "x, \"y\"");
  BOOST_TEST(!read_csv(dir / "absent.csv"));
  write(dir / "bad.csv", "a,b\n1,2,3\n");
  BOOST_CHECK_THROW(read_csv(dir / "bad.csv"), std::runtime_error);
  fs::remove_all(dir);
}

// The claims are data: the verdict comes from the row's expectation alone, and each kind flips at
// its bound (a measurement exactly at the bound is on the side the kind's words say).
BOOST_AUTO_TEST_CASE(each_expectation_kind_flips_at_its_bound) {
  const auto number = [](double x) { return measurement::of(x, ""); };
  BOOST_TEST(meets(equal_to(12), number(12)));
  BOOST_TEST(!meets(equal_to(12), number(13)));
  BOOST_TEST(meets(relative_within(700, 0.2), number(840)));
  BOOST_TEST(!meets(relative_within(700, 0.2), number(841)));
  BOOST_TEST(meets(absolute_within(0.12, 0.05), number(0.16)));
  BOOST_TEST(!meets(absolute_within(0.12, 0.05), number(0.18)));
  BOOST_TEST(meets(at_most(1.05), number(1.05)));
  BOOST_TEST(!meets(at_most(1.05), number(1.0500001)));
  BOOST_TEST(meets(at_least(38), number(38)));
  BOOST_TEST(!meets(at_least(38), number(37.9)));
  BOOST_TEST(!meets(below(0.25), number(0.25)));
  BOOST_TEST(meets(below(0.25), number(0.2499)));
  BOOST_TEST(!meets(between_0_and(0.5), number(0)));
  BOOST_TEST(meets(between_0_and(0.5), number(0.3)));
  BOOST_TEST(!meets(between_0_and(0.5), number(0.5)));
  BOOST_TEST(!meets(at_least(0.8), number(std::nan(""))));  // a NaN never holds
  BOOST_TEST(meets(each_within(0.1), measurement::of_deviations({0.1, -0.05}, "")));
  BOOST_TEST(!meets(each_within(0.1), measurement::of_deviations({0.1, std::nan("")}, "")));  // a missing row
  BOOST_TEST(!meets(each_within(0.1), measurement::of_deviations({}, "")));
  BOOST_TEST(meets(same_names({"a", "b"}), measurement::of_names({"a", "b"}, "")));
  BOOST_TEST(!meets(same_names({"a", "b"}), measurement::of_names({"b", "a"}, "")));
  BOOST_TEST(meets(same_name_set({"a", "b"}), measurement::of_names({"b", "a"}, "")));
  BOOST_TEST(!meets(same_name_set({"a", "b"}), measurement::of_names({"a"}, "")));
  BOOST_TEST(meets(names_differ(), measurement::of_names({"a", "b"}, "")));
  BOOST_TEST(!meets(names_differ(), measurement::of_names({"a", "a"}, "")));
  BOOST_TEST(meets(property_holds(), measurement::of_flag(true, "")));
  BOOST_TEST(!meets(property_holds(), measurement::of_flag(false, "")));
}

BOOST_AUTO_TEST_CASE(accuracy_ratio_rows_flip_at_the_tolerance) {
  const auto dir = report_test::scratch("audit-ratio");
  const auto claim = "Water: P1 BAC (5) about 1.7 times more accurate than RS4 S5 McLachlan CBA";
  const auto saving = "Water: P1 BAC (5) decreases the computation time by 12 %";
  // RS4 S5 / P1 = 1.7: holds; saving 1 - 1.7^(-1/4) = 12.4 %: holds.
  write(dir / "fig5_water_dedicated.csv", fourth_order_curves({{"N2 BAC (2)", 8.0}, {"P1 BAC (5)", 1.0},
                                                                {"R ABC (4)", 9.0}, {"RS4-S5-McLachlan:CBA", 1.7}}));
  auto rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, claim).verdict) == static_cast<int>(audit_verdict::holds));
  BOOST_TEST(find_row(rows, claim).value.rfind("1.7×", 0) == 0);
  BOOST_TEST(static_cast<int>(find_row(rows, saving).verdict) == static_cast<int>(audit_verdict::holds));
  BOOST_TEST(static_cast<int>(find_row(rows, "Water: P1 BAC (5) about 8 times").verdict) == static_cast<int>(audit_verdict::holds));
  // 1.7 × 1.25 = 2.125: 25 % off, beyond 20 %; the saving 17.2 % is beyond 5 points of 12 %.
  write(dir / "fig5_water_dedicated.csv", fourth_order_curves({{"N2 BAC (2)", 8.0}, {"P1 BAC (5)", 1.0},
                                                                {"R ABC (4)", 9.0}, {"RS4-S5-McLachlan:CBA", 2.125}}));
  rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, claim).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  BOOST_TEST(static_cast<int>(find_row(rows, saving).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  // Slopes of exact h^4 curves: 4.
  const auto& slopes = find_row(rows, "All dedicated and reference 4th-order schemes show slope 4");
  BOOST_TEST(static_cast<int>(slopes.verdict) == static_cast<int>(audit_verdict::holds));
  // The same files, but the accuracy section did not run in this run: no number, whatever the folder holds.
  auto in = all_sections(dir);
  in.sections_run.erase("accuracy");
  rows = audit_rows_from_reports(in);
  BOOST_TEST(static_cast<int>(find_row(rows, claim).verdict) == static_cast<int>(audit_verdict::not_computed));
  BOOST_TEST(verdict_text(find_row(rows, claim)) == "not computed in this run (section accuracy)");
  BOOST_TEST(find_row(rows, claim).value == "—");
  // The section ran but its file is missing.
  fs::remove(dir / "fig5_water_dedicated.csv");
  rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, claim).verdict) == static_cast<int>(audit_verdict::not_computed));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(map_rows_follow_the_map_file) {
  const auto dir = report_test::scratch("audit-maps");
  const auto some = "N beats RS4 S5 McLachlan (best permutations, × (12/9)^4) only for some bodies";
  const auto only_asymmetric = "P beats RS4 S5 McLachlan (× (12/11)^4) only for very asymmetric bodies";
  // N wins at one body of five (the most asymmetric): "only some" holds; P wins far from the tops only.
  write(dir / "map-N.jsonl", map_file("N", {2.0, 0.5, 0.4, 0.3, 0.01}));
  write(dir / "map-P.jsonl", map_file("P", {1.5, 1.2, 0.5, 0.5, 0.1}));
  auto rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, some).verdict) == static_cast<int>(audit_verdict::holds));
  BOOST_TEST(static_cast<int>(find_row(rows, "RS4 S5 McLachlan is especially more accurate").verdict) ==
             static_cast<int>(audit_verdict::holds));
  BOOST_TEST(static_cast<int>(find_row(rows, only_asymmetric).verdict) == static_cast<int>(audit_verdict::holds));
  // N wins at four of five, P also near a symmetric top (3/10, 49/50): both flip.
  write(dir / "map-N.jsonl", map_file("N", {2.0, 1.5, 1.4, 1.3, 0.01}));
  write(dir / "map-P.jsonl", map_file("P", {1.5, 1.2, 0.5, 0.5, 1.1}));
  rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, some).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  BOOST_TEST(static_cast<int>(find_row(rows, only_asymmetric).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  // The maps given with --maps are read from there.
  const auto given = dir / "given";
  write(given / "map-N.jsonl", map_file("N", {2.0, 0.5, 0.4, 0.3, 0.01}));
  auto in = all_sections(dir);
  in.maps_folder = given;
  rows = audit_rows_from_reports(in);
  BOOST_TEST(static_cast<int>(find_row(rows, some).verdict) == static_cast<int>(audit_verdict::holds));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(measured_ratio_rows_read_the_truth_file) {
  const auto dir = report_test::scratch("audit-truth");
  const auto corr = "The analytic remainder predicts the measured gain of the best N";
  const auto flips = "The analytic verdict \"N better";
  auto rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, corr).verdict) == static_cast<int>(audit_verdict::not_computed));
  const std::string header = "I1,I2,I3,family,best,analytic_ratio,measured_ratio_h,measured_ratio_cpu\n";
  // Same order, same side of 1 at every body: holds.
  write(dir / "maps-truth" / "measured-ratios.csv", header + "0.3,0.7,1,N,N1:ABC:1,0.5,0.6,0.6\n0.3,0.8,1,N,N1:ABC:1,0.8,0.9,0.9\n"
                                                             "0.4,0.7,1,N,N1:ABC:1,1.5,1.4,1.4\n0.4,0.8,1,N,N1:ABC:1,2.0,2.5,2.5\n");
  rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, corr).verdict) == static_cast<int>(audit_verdict::holds));
  BOOST_TEST(static_cast<int>(find_row(rows, flips).verdict) == static_cast<int>(audit_verdict::holds));
  // Reversed order, and the verdict flips at two of four bodies.
  write(dir / "maps-truth" / "measured-ratios.csv", header + "0.3,0.7,1,N,N1:ABC:1,0.5,2.5,2.5\n0.3,0.8,1,N,N1:ABC:1,0.8,1.4,1.4\n"
                                                             "0.4,0.7,1,N,N1:ABC:1,1.5,0.9,0.9\n0.4,0.8,1,N,N1:ABC:1,2.0,0.6,0.6\n");
  rows = audit_rows_from_reports(all_sections(dir));
  BOOST_TEST(static_cast<int>(find_row(rows, corr).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  BOOST_TEST(static_cast<int>(find_row(rows, flips).verdict) == static_cast<int>(audit_verdict::does_not_hold));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(the_section_alone_writes_its_table_cheaply) {
  const auto dir = report_test::scratch("audit-section");
  // A stale file of another run must not be read when its section does not run now.
  write(dir / "solutions_sphere.json", "{\"solutions\":[]}");
  report_options o;
  o.out_dir = dir;
  o.sections = {"audit"};
  const std::clock_t start = std::clock();
  const auto s = write_section("audit", o);
  const double cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  BOOST_TEST_MESSAGE("audit section alone: " << cpu << " s CPU");  // its budget is measured by the report, not asserted here
  const auto csv = read_csv(dir / "audit" / "audit.csv");
  BOOST_REQUIRE(csv);
  BOOST_TEST(csv->header.size() == 5u);
  bool stale_read = false, some_holds = false;
  for (const auto& r : csv->rows) {
    if (r[0].rfind("Spherical top: the N integrators have 12", 0) == 0) stale_read = r[4] != "not computed in this run (section dedicated)";
    some_holds = some_holds || r[4] == "holds";
  }
  BOOST_TEST(!stale_read);
  BOOST_TEST(some_holds);  // the rows computed by the section itself (costs, grid, R family)
  BOOST_TEST(fs::exists(dir / "audit" / "audit.json"));
  BOOST_TEST(s.markdown.find("| statement (LV) |") != std::string::npos);
  fs::remove_all(dir);
}

// The costliest row of the section: with the dedicated section's P file present, the ten systems
// of smallest ‖H_R5‖ are solved again and integrated. The file here lists them (names only; the
// remainders give their order), as the dedicated section writes them for water.
BOOST_AUTO_TEST_CASE(the_p_choice_row_solves_and_measures_the_listed_systems) {
  const auto dir = report_test::scratch("audit-p");
  const std::vector<std::tuple<std::string, std::string, int>> listed = {
      {"P6", "ABC", 3}, {"P4", "ABC", 2}, {"P8", "ABC", 3}, {"P1", "BAC", 5}, {"P14", "ACB", 2},
      {"P9", "CBA", 5}, {"P14", "CAB", 5}, {"P14", "ABC", 4}, {"P6", "BAC", 7}, {"P11", "CAB", 5}};
  nlohmann::json file = {{"solutions", nlohmann::json::array()}};
  for (std::size_t k = 0; k < listed.size(); ++k)
    file["solutions"].push_back({{"scheme", std::get<0>(listed[k])}, {"perm", std::get<1>(listed[k])},
                                 {"label", std::get<2>(listed[k])}, {"analytic_remainder", 0.001 * static_cast<double>(k + 1)}});
  write(dir / "solutions_water_P.json", file.dump());
  report_options o;
  o.out_dir = dir;
  o.sections = {"dedicated", "audit"};
  const std::clock_t start = std::clock();
  write_section("audit", o);
  const double cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  BOOST_TEST_MESSAGE("audit section with the P systems: " << cpu << " s CPU");
  const auto csv = read_csv(dir / "audit" / "audit.csv");
  BOOST_REQUIRE(csv);
  bool seen = false;
  for (const auto& r : csv->rows)
    if (r[0].rfind("Water: among the P integrators of smallest analytic remainder", 0) == 0) {
      seen = true;
      BOOST_TEST(r[4] == "holds");  // P1 BAC (5) measured best of the ten, as LV found
      BOOST_TEST(r[2].find("P1 BAC (5) is #4 of 10") != std::string::npos);
    }
  BOOST_TEST(seen);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()  // audit_table_test
