// The rotlie binary end to end: JSON shapes, bad input (one line on stderr, non-zero exit,
// never a crash), and the report's output folder (its symbolic sections).
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <map>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

std::size_t line_count(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

void expect_clean_error(const std::string& args, const std::string& must_mention) {
  const auto r = run(args);
  BOOST_TEST_CONTEXT("rotlie " << args << " → status " << r.status << ", stderr: " << r.err) {
    BOOST_TEST(r.status != 0);
    BOOST_TEST(r.status < 126);  // an error exit, not a crash (a signal would give 128 + n)
    BOOST_TEST(line_count(r.err) == 1u);
    BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u);
    BOOST_TEST(r.err.find(must_mention) != std::string::npos);
    BOOST_TEST(r.out.empty());
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(dims_json_shape_and_values) {
  const auto r = run("dims --max-order 5 --json");
  BOOST_REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& orders = j.at("orders");
  BOOST_REQUIRE(orders.size() == 5u);
  const int dims[] = {3, 1, 2, 3, 6};
  for (int k = 0; k < 5; ++k) {
    BOOST_TEST(orders[k].at("order").get<int>() == k + 1);
    BOOST_TEST(orders[k].at("dim").get<int>() == dims[k]);
    BOOST_TEST(orders[k].at("theorem1").get<bool>());
    BOOST_TEST(orders[k].at("bound").get<int>() == dims[k]);
    BOOST_TEST(orders[k].at("attained").get<bool>());
  }
  BOOST_TEST(orders[0].at("theorem2").is_null());
  BOOST_TEST(orders[1].at("theorem2").is_null());
  BOOST_TEST(orders[2].at("theorem2").get<bool>());
  BOOST_TEST(orders[4].at("theorem2").get<bool>());
  BOOST_TEST(r.err.empty());
}

BOOST_AUTO_TEST_CASE(dims_text_has_one_line_per_order) {
  const auto r = run("dims --max-order 12");
  BOOST_REQUIRE(r.status == 0);
  BOOST_TEST(line_count(r.out) == 13u);  // header + 12 orders
}

BOOST_AUTO_TEST_CASE(stages_json_shape) {
  const auto r = run("stages --max-order 10 --json");
  BOOST_REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& blocks = j.at("blocks");
  BOOST_REQUIRE(blocks.size() == 4u);
  const char* names[] = {"general-2", "general-3", "rigid-RS", "rigid-ABC"};
  for (int b = 0; b < 4; ++b) {
    BOOST_TEST(blocks[b].at("name").get<std::string>() == names[b]);
    BOOST_REQUIRE(blocks[b].at("rows").size() == 10u);
    for (const auto* key : {"order", "dim", "equations_ns", "total_ns", "equations_s", "total_s", "stages_ns", "stages_s"})
      BOOST_TEST(blocks[b].at("rows")[0].contains(key), key);
  }
  const auto& abc4 = blocks[3].at("rows")[3];  // rigid ABC, order 4: the 9-stage N integrators
  BOOST_TEST(abc4.at("stages_s").get<int>() == 9);
  BOOST_TEST(abc4.at("equations_s").is_null());
  BOOST_TEST(blocks[1].at("rows")[3].at("stages_s_quoted_from").get<std::string>().find("Tang") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_orders_get_one_line_and_a_nonzero_exit) {
  for (const std::string cmd : {"dims", "stages"}) {
    expect_clean_error(cmd + " --max-order 0", "--max-order");
    expect_clean_error(cmd + " --max-order -4", "--max-order");
    expect_clean_error(cmd + " --max-order abc", "not an integer");
    expect_clean_error(cmd + " --max-order 2.5", "not an integer");
    expect_clean_error(cmd + " --max-order ''", "--max-order must not be empty");
    expect_clean_error(cmd + " --max-order 1000000", "at most");
    expect_clean_error(cmd + " --max-order 99999999999999999999999999", "at most");
    expect_clean_error(cmd + " --max-order -99999999999999999999999999", "at least");
    expect_clean_error(cmd, "--max-order");
  }
  expect_clean_error("frobnicate", "frobnicate");
  expect_clean_error("", "subcommand");
}

BOOST_AUTO_TEST_CASE(remainder_json_shape) {
  const auto r = run("remainder --scheme N4 --order 5 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("word").get<std::string>() == "ABCABACBA");
  BOOST_TEST(j.at("split").get<std::string>() == "ABC");
  BOOST_TEST(j.at("perm").get<std::string>() == "ABC");
  BOOST_REQUIRE(j.at("orders").size() == 4u);  // orders 2, 3, 4, 5
  const auto& o3 = j.at("orders")[1];
  BOOST_TEST(o3.at("order").get<int>() == 3);
  BOOST_TEST(o3.at("terms").size() == 3u);
  BOOST_TEST((o3.at("terms")[0].at("G") == nlohmann::json::array({2, 2, 0})));
  BOOST_TEST(!o3.at("terms")[0].contains("value"));  // symbolic: no number
  BOOST_TEST(j.at("orders")[3].at("terms").size() == 7u);  // the seven monomials of eq. (62)
  BOOST_TEST(j.at("orders")[0].at("terms").empty());       // symmetric: no H_R2
}

BOOST_AUTO_TEST_CASE(remainder_of_table_4s_best_scheme_vanishes_at_third_order) {
  // N2 BAC (2) for water, eq. (74): the 42-digit coefficients leave H_R3 at round-off of those digits.
  const auto r = run("remainder --scheme N2 --perm BAC --inertia water --order 3 --json --coeffs "
                     "a1=4.5504624774591050429019276281136041301731e-2,a2=1.5208328361334726621353294430175796767150e-1");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("word").get<std::string>() == "BABCBCBAB");  // eq. (73)
  for (const auto& t : j.at("orders")[1].at("terms")) BOOST_TEST(std::abs(t.at("value").get<double>()) < 1e-38);
  // while the same word with other coefficients does not
  const auto other = nlohmann::json::parse(run("remainder --scheme N2 --perm BAC --inertia water --order 3 --json "
                                               "--coeffs a1=1/20,a2=3/20").out);
  BOOST_TEST(std::abs(other.at("orders")[1].at("terms")[0].at("value").get<double>()) > 1e-4);
}

BOOST_AUTO_TEST_CASE(remainder_bad_input) {
  expect_clean_error("remainder --scheme ABD", "letter 'D'");
  expect_clean_error("remainder --scheme ''", "empty");
  expect_clean_error("remainder --scheme 'sin()'", "letter 's'");
  expect_clean_error("remainder --scheme N4 --order 0", "--order");
  expect_clean_error("remainder --scheme N4 --order 10", "at most");
  expect_clean_error("remainder --scheme N4 --order x", "not an integer");
  expect_clean_error("remainder --scheme N4 --coeffs z9=1", "not a coefficient");
  expect_clean_error("remainder --scheme N4 --coeffs b2=1", "fixed by the first-order conditions");
  expect_clean_error("remainder --scheme N4 --coeffs a1=abc", "not a finite number");
  expect_clean_error("remainder --scheme N4 --coeffs a1=nan", "not a finite number");
  expect_clean_error("remainder --scheme N4 --coeffs a1", "name=value");
  expect_clean_error("remainder --scheme N4 --coeffs a1=1,a1=2", "twice");
  expect_clean_error("remainder --scheme N4 --inertia 1,2", "three values");
  expect_clean_error("remainder --scheme N4 --inertia nan,1,1", "not a finite number");
  expect_clean_error("remainder --scheme N4 --inertia 0.345,0.653,1", "eq. (77)");
  expect_clean_error("remainder --scheme N4 --inertia -1,1,1", "not positive");
  expect_clean_error("remainder --scheme N4 --perm XYZ", "unknown permutation");
  expect_clean_error("remainder --scheme N4 --split XY", "--split");
  expect_clean_error("remainder --scheme N4 --split RS", "ABC scheme");
  expect_clean_error("remainder --scheme N4 --latex --json", "exclude");
}

BOOST_AUTO_TEST_CASE(solve_json_shape_for_water) {
  const auto r = run("solve --family N --inertia water --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("family").get<std::string>() == "N");
  BOOST_TEST(j.at("real_solutions").get<int>() == 90);  // the paper's count (section 4.3)
  BOOST_TEST((j.at("inertia") == nlohmann::json::array({"2555/7344", "19187/29376", "1"})));
  const auto& best = j.at("solutions")[0];
  BOOST_TEST(best.at("scheme").get<std::string>() == "N2");
  BOOST_TEST(best.at("perm").get<std::string>() == "BAC");
  BOOST_TEST(best.at("label").get<int>() == 2);
  BOOST_TEST(best.at("word").get<std::string>() == "BABCBCBAB");
  BOOST_TEST(best.at("coefficients").at("a1").get<std::string>().rfind("4.5504624774591050429019276281136041301", 0) == 0u);
  BOOST_TEST(std::abs(best.at("analytic_remainder").get<double>() - 0.0106) < 0.00005);
  BOOST_TEST(best.at("residual").get<double>() < 1e-35);
  double previous = 0;
  for (const auto& s : j.at("solutions")) {
    BOOST_TEST(s.at("analytic_remainder").get<double>() >= previous);
    previous = s.at("analytic_remainder").get<double>();
  }
}

BOOST_AUTO_TEST_CASE(solve_p_family_gives_eq_76_first) {
  const auto r = run("solve --family P --scheme P1 --perm BAC --inertia water --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("family").get<std::string>() == "P");
  BOOST_TEST(j.at("real_solutions").get<int>() == 8);
  const auto& best = j.at("solutions").at(0);
  BOOST_TEST(best.at("label").get<int>() == 5);
  BOOST_TEST(best.at("word").get<std::string>() == "BABABCBABAB");  // eq. (75)
  BOOST_TEST(best.at("coefficients").at("a1").get<std::string>().rfind("2.65761371902173917814834651897593444", 0) == 0u);
  BOOST_TEST(j.at("systems").at(0).at("eliminant_degree").get<int>() > 0);
}

BOOST_AUTO_TEST_CASE(solve_writes_scheme_tables_that_meet_the_contract) {
  const fs::path out = scratch() / "tables";
  const auto r = run("solve --family N --scheme N4 --perm BCA --inertia water --digits 45 --out " + out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const std::string table = slurp(out / "N4_BCA_1.scheme");
  BOOST_TEST(table.find("word BCABCBACB") != std::string::npos);
  // Σ of each letter's coefficients is 1 and the stages read the same backwards.
  std::istringstream in(table);
  std::string line;
  std::map<char, double> sum;
  std::vector<std::string> names;
  while (std::getline(in, line)) {
    if (line.rfind("stage ", 0) != 0) continue;
    std::istringstream f(line.substr(6));
    char letter;
    std::string name, value;
    f >> letter >> name >> value;
    const std::string mantissa = value.substr(0, value.find('e'));  // whole value when there is no exponent
    BOOST_TEST(std::count_if(mantissa.begin(), mantissa.end(), ::isdigit) >= 45, value);  // ≥ 45 significant digits
    sum[letter] += std::stod(value);
    names.push_back(std::string(1, letter) + name);
  }
  BOOST_REQUIRE(names.size() == 9u);
  for (const auto& [letter, total] : sum) BOOST_TEST(std::abs(total - 1) < 1e-14, letter);
  BOOST_TEST(std::equal(names.begin(), names.end(), names.rbegin()));
}

BOOST_AUTO_TEST_CASE(solve_two_parameter_family_writes_a_table_the_numeric_side_runs) {
  const fs::path out = scratch() / "two_parameter";
  const auto r = run("solve --family QRS --scheme RSRSRSRSRSR --perm CBA --inertia water --starts 30 --json --out " + out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("family").get<std::string>() == "QRS");
  const auto& s = j.at("systems").at(0);
  BOOST_TEST(s.at("name").get<std::string>() == "QRS:RSRSRSRSRSR:CBA");
  BOOST_REQUIRE(s.at("polished").get<bool>());
  BOOST_TEST(s.at("distinct_minima").get<int>() >= 1);
  BOOST_TEST(std::stod(s.at("projected_gradient").get<std::string>()) < 1e-40);
  for (const auto& v : s.at("reduced_hessian")) BOOST_TEST(v.get<double>() > 0);  // a local minimum
  // The table it wrote loads on the numeric side (its checks) and runs at order 4.
  const auto o = run("order --scheme " + (out / "QRS_RSRSRSRSRSR_CBA.scheme").string() + " --inertia water --min-level 3 --max-level 7 --json");
  BOOST_REQUIRE_MESSAGE(o.status == 0, o.err);
  BOOST_TEST(std::abs(nlohmann::json::parse(o.out).at("slope").get<double>() - 4) < 0.15);
}

BOOST_AUTO_TEST_CASE(solve_bad_input) {
  expect_clean_error("solve --family N --inertia 0.345,0.653,1", "eq. (77)");
  expect_clean_error("solve --family N --inertia 0,1,1", "not positive");
  expect_clean_error("solve --family N --inertia -1,1,1", "not positive");
  expect_clean_error("solve --family N --inertia nan,1,1", "not a finite number");
  expect_clean_error("solve --family N", "--inertia is required");
  expect_clean_error("solve --family X --inertia water", "--family");
  expect_clean_error("solve --family N --scheme N9 --inertia water", "not in the N family");
  expect_clean_error("solve --family N --perm XYZ --inertia water", "--perm");
  expect_clean_error("solve --family N --digits 5 --inertia water", "at least 10");
  expect_clean_error("solve --family N --digits 99999 --inertia water", "at most");
  expect_clean_error("solve --family P --scheme N2 --inertia water", "not in the P family (P1 … P15)");
  expect_clean_error("solve --family R --scheme P1 --inertia water", "not in the R family (R)");
}

BOOST_AUTO_TEST_CASE(solve_symmetric_top_where_the_scheme_degenerates) {
  // With I1 = I2 the R part of RS splitting ABC vanishes: nothing to solve for.
  expect_clean_error("solve --family R --perm ABC --inertia 1/2,1/2,1", "R part G1²/2 (1/I1 − 1/I2) vanishes");
  expect_clean_error("solve --family R --inertia sphere", "undefined for this body");
  // Over all permutations the undefined ones are warned about and the others solved.
  const auto r = run("solve --family R --inertia 1/2,1/2,1 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  BOOST_TEST(r.err.find("warning: R ABC is undefined") != std::string::npos);
  BOOST_TEST(nlohmann::json::parse(r.out).at("real_solutions").get<int>() > 0);
}

BOOST_AUTO_TEST_CASE(solve_reports_a_singular_elimination) {
  // On the flat body (1/4, 3/4, 1) the two conditions of N1 ABC share a factor: a curve of solutions.
  expect_clean_error("solve --family N --scheme N1 --perm ABC --inertia 1/4,3/4,1",
                     "flat body (I3 = I1 + I2): the two conditions share a factor");
}

BOOST_AUTO_TEST_CASE(integrate_json_shape_and_value) {
  const auto r = run("integrate --scheme N2:BAC:2 --inertia water --h 1/64 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("scheme").get<std::string>() == "N2:BAC:2");
  BOOST_REQUIRE(j.at("points").size() == 1u);
  const auto& p = j.at("points")[0];
  BOOST_TEST(p.at("h").get<double>() == 1.0 / 64);
  BOOST_TEST(p.at("h_over_C").get<double>() == 1.0 / 64 / 9, boost::test_tools::tolerance(1e-15));  // 9 stages, 9 C0
  BOOST_TEST(p.at("cpu_s").get<double>() > 0);
  // 4th order: the error at h = 1/64 is far below that of leapfrog at the same step.
  const auto leap = nlohmann::json::parse(run("integrate --scheme ABCBA2:BAC --inertia water --h 1/64 --json").out);
  BOOST_TEST(p.at("error").get<double>() > 0);
  BOOST_TEST(p.at("error").get<double>() * 1e3 < leap.at("points")[0].at("error").get<double>());
}

BOOST_AUTO_TEST_CASE(order_json_gives_the_declared_slope) {
  const auto r = run("order --scheme ABCBA2 --inertia water --min-level 3 --max-level 9 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("points").size() == 7u);
  BOOST_TEST(std::abs(j.at("slope").get<double>() - 2) < 0.1);
}

BOOST_AUTO_TEST_CASE(exact_json_conserves_the_invariants) {
  const auto r = run("exact --inertia water --T 7/3 --G0 1,1,1 --json");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.at("T").get<double>() == 7.0 / 3, boost::test_tools::tolerance(1e-15));
  const std::array<double, 3> I{10220.0 / 29376, 19187.0 / 29376, 1};
  double g2 = 0, energy = 0;
  for (int i = 0; i < 3; ++i) {
    const double g = j.at("G")[i].get<double>();
    g2 += g * g;
    energy += g * g / (2 * I[i]);
  }
  BOOST_TEST(g2 == 3.0, boost::test_tools::tolerance(1e-13));
  BOOST_TEST(energy == (1 / I[0] + 1 / I[1] + 1 / I[2]) / 2, boost::test_tools::tolerance(1e-13));
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += j.at("Q")[a][k].get<double>() * j.at("Q")[b][k].get<double>();
      BOOST_TEST(std::abs(dot - (a == b ? 1 : 0)) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(numeric_commands_bad_input) {
  expect_clean_error("integrate --scheme ABCBA2 --inertia water --h 0", "--h must be positive");
  expect_clean_error("integrate --scheme ABCBA2 --inertia water --h -1/64", "--h must be positive");
  expect_clean_error("integrate --scheme ABCBA2 --inertia water --h 1/64 --T 0", "--T must be positive");
  expect_clean_error("integrate --scheme ABCBA2 --inertia water --h 1e-9 --T 1000", "over the limit");
  expect_clean_error("integrate --scheme ABCBA2 --inertia nan,1,1 --h 1/64", "not a finite number");
  expect_clean_error("integrate --scheme ABCBA2 --inertia water --h nan", "--h");
  expect_clean_error("integrate --scheme FOO --inertia water --h 1/64", "unknown scheme");
  expect_clean_error("integrate --scheme N2:XYZ:2 --inertia water --h 1/64", "unknown permutation");
  expect_clean_error("integrate --scheme N2:BAC:9 --inertia water --h 1/64", "no label 9");
  expect_clean_error("exact --inertia water --T -1", "--T must be positive");
  expect_clean_error("order --scheme ABCBA2 --inertia water --min-level 5 --max-level 2", "level");
  // A table whose A coefficients do not sum to 1.
  const fs::path table = scratch() / "bad.scheme";
  std::ofstream(table) << "format_version 1\nname broken\nsplit ABC\nword ABA\norder 2\nsymmetric true\nstages 3\n"
                          "stage A a1 0.4\nstage B b1 1\nstage A a1 0.4\n";
  expect_clean_error("integrate --scheme " + table.string() + " --inertia water --h 1/64", "sum to 0.800000, not 1");
}

// The sections that derive and solve (seconds); every section of the quick report is
// report_quick_cli_test's (slow label: minutes).
BOOST_AUTO_TEST_CASE(report_writes_a_complete_folder) {
  const fs::path out = scratch() / "report";
  const auto r = run("report --quick --sections lie-algebra,remainders,dedicated,audit --out " + out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  for (const auto* f : {"index.md", "table1.md", "table1.tex", "table1.json", "dims.md", "dims.json"})
    BOOST_TEST(fs::is_regular_file(out / f), f);
  for (const auto& e : fs::directory_iterator(out))
    BOOST_TEST(e.path().string().find(".tmp.") == std::string::npos, "left-over " << e.path());
  BOOST_TEST(slurp(out / "index.md").find("Table 1") != std::string::npos);
  BOOST_TEST(nlohmann::json::parse(slurp(out / "table1.json")).at("blocks").size() == 4u);
}

BOOST_AUTO_TEST_CASE(report_into_an_impossible_folder_fails_cleanly) {
  const fs::path blocker = scratch() / "a-file";
  std::ofstream(blocker) << "x";
  expect_clean_error("report --quick --out " + (blocker / "sub").string(), "cannot create");
}

BOOST_AUTO_TEST_CASE(bch_prints_the_same_series_on_any_number_of_threads) {
  // log(e^X e^Y) to degree 6: 23 Lyndon words, among them AB with 1/2 and AAB with 1/12 (BCH's classical terms)
  const auto one = run("bch --series XY --degree 6 --json");
  BOOST_REQUIRE_MESSAGE(one.status == 0, one.err);
  const auto j = nlohmann::json::parse(one.out);
  BOOST_TEST(j.at("series") == "XY");
  BOOST_TEST(j.at("degree") == 6);
  BOOST_TEST(j.at("terms").size() == 23u);
  std::map<std::string, std::string> c;
  for (const auto& t : j.at("terms")) c[t.at("word")] = t.at("coefficient");
  BOOST_TEST(c["AB"] == "1/2");
  BOOST_TEST(c["AAB"] == "1/12");
  BOOST_TEST(c["ABB"] == "1/12");
  BOOST_TEST(c["AABB"] == "1/24");
  for (const char* threads : {"2", "3", "7"}) {
    BOOST_TEST(run(std::string("bch --series XY --degree 6 --json --threads ") + threads).out == one.out, threads);
    BOOST_TEST(run(std::string("bch --series XYZ --degree 5 --threads ") + threads).out == run("bch --series XYZ --degree 5").out,
               threads);
  }
}

// `rotlie --version` names the project's version (CMake's PROJECT_VERSION), exit 0.
BOOST_AUTO_TEST_CASE(version_names_the_release) {
  const auto r = run("--version");
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(r.out == "rotlie 0.1.0\n");
}

BOOST_AUTO_TEST_SUITE_END()  // cli_test
