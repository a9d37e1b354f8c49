// Scheme tables on the numeric side: the reference schemes meet the contract (Σ per part = 1,
// palindromes, stage counts and costs of LV section 4 and REFERENCE.md §1.4), their coefficients
// equal the closed forms, permutations substitute letters, and bad tables are refused.
#include <boost/test/unit_test.hpp>

#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>

#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/schemes/same_body.hpp"

BOOST_AUTO_TEST_SUITE(scheme_table_test)

using namespace rotlie::schemes;

BOOST_AUTO_TEST_CASE(stage_counts_and_costs) {
  struct row {
    const char* name;
    std::size_t stages;
    int cost;
  };
  // REFERENCE.md §1.4 and LV section 4.1 / 5.2
  for (const auto& r : std::vector<row>{{"ABCBA2", 5, 5},
                                        {"RSR2", 3, 4},
                                        {"ABCBA4-SS3-Yoshida", 13, 13},
                                        {"RSR4-SS3-Yoshida", 7, 8},
                                        {"ABCBA4-SS5-Suzuki", 21, 21},
                                        {"RSR4-SS5-McLachlan", 11, 12},
                                        {"RS4-S4-McLachlan", 9, 10},
                                        {"RS4-S5-McLachlan", 11, 12},
                                        {"ABC4-S4-McLachlan", 17, 17},
                                        {"ABC4-S5-McLachlan", 21, 21}}) {
    const auto t = reference_scheme(r.name);
    BOOST_REQUIRE(t);
    BOOST_TEST(t->stages.size() == r.stages, r.name);
    BOOST_TEST(cost_in_rotations(*t) == r.cost, r.name);
  }
}

BOOST_AUTO_TEST_CASE(every_reference_scheme_meets_the_contract_in_every_permutation) {
  for (const auto& name : reference_scheme_names())
    for (const char* p : {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"}) {
      const auto t = reference_scheme(name + ":" + p);
      BOOST_REQUIRE(t);
      BOOST_CHECK_NO_THROW(check_scheme_table(*t));
      for (const auto& s : t->stages) BOOST_TEST(s.value.size() >= 36u);  // float128 precision
    }
}

BOOST_AUTO_TEST_CASE(coefficients_equal_the_closed_forms) {
  auto value = [](const scheme_table& t, std::size_t i) { return std::stold(t.stages[i].value); };
  const auto y = *reference_scheme("RSR4-SS3-Yoshida");  // R: w1/2, (w1+w0)/2, …; S: w1, w0, w1
  const long double w1 = 1 / (2 - std::cbrt(2.0L));
  BOOST_TEST(std::fabs(value(y, 1) - w1) < 1e-18L);
  BOOST_TEST(std::fabs(value(y, 0) - w1 / 2) < 1e-18L);
  BOOST_TEST(std::fabs(value(y, 3) - (1 - 2 * w1)) < 1e-18L);
  const auto s5 = *reference_scheme("RS4-S5-McLachlan");  // x1 = (14 − √19)/108, y1 = 2/5
  BOOST_TEST(std::fabs(value(s5, 0) - (14 - std::sqrt(19.0L)) / 108) < 1e-18L);
  BOOST_TEST(std::fabs(value(s5, 1) - 0.4L) < 1e-18L);
  const auto m5 = *reference_scheme("RSR4-SS5-McLachlan");  // γ1 = 0.28, Σγ³ = 0
  const long double g1 = value(m5, 1), g2 = value(m5, 3), g3 = value(m5, 5);
  BOOST_TEST(std::fabs(g1 - 0.28L) < 1e-18L);
  BOOST_TEST(std::fabs(2 * g1 * g1 * g1 + 2 * g2 * g2 * g2 + g3 * g3 * g3) < 1e-17L);
  // S5 in α form (REFERENCE.md §1.2): the first stages are α1, α1, α1 + α2 for A, B, C
  const auto a5 = *reference_scheme("ABC4-S5-McLachlan");
  BOOST_TEST(a5.word.substr(0, 4) == "ABCB");
  BOOST_TEST(std::fabs(value(a5, 2) - (0.08926945422647524488669L + 0.31073054577352475511331L)) < 1e-18L);
}

BOOST_AUTO_TEST_CASE(permutations_substitute_letters) {
  const auto t = *reference_scheme("ABCBA2:BAC");
  BOOST_TEST(t.word == "BACAB");
  const auto r = *reference_scheme("RS4-S5-McLachlan:CBA");
  BOOST_TEST(r.word.front() == 'R');
  BOOST_TEST(rs_axes(r)[0] == 2);  // R about body axis 3, S about axis 1 (REFERENCE.md §0.1)
  BOOST_TEST(rs_axes(r)[2] == 0);
  BOOST_CHECK_THROW(reference_scheme("ABCBA2:XYZ"), std::invalid_argument);
  try {  // found by fuzz_scheme_name: the permutation's bytes were echoed raw (a form feed, NULs)
    reference_scheme(std::string("ABCBA2:\x0c\0\0\0\xff", 12));
    BOOST_ERROR("accepted a bad permutation");
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("\\x0C\\x00\\x00\\x00\\xFF") != std::string::npos, m);
    BOOST_TEST(m.find('\f') == std::string::npos);
  }
  BOOST_TEST(!reference_scheme("Yoshida"));
}

BOOST_AUTO_TEST_CASE(bad_tables_are_refused_with_a_reason) {
  const std::string good =
      "format_version 1\nname t\nsplit ABC\nword ABCBA\npermutation ABC\norder 2\nsymmetric true\nstages 5\n"
      "stage A a1 0.5\nstage B b1 0.5\nstage C c1 1\nstage B b1 0.5\nstage A a1 0.5\n";
  BOOST_CHECK_NO_THROW(parse_scheme_table(good));
  auto refuses = [](const std::string& text, const std::string& reason) {
    try {
      parse_scheme_table(text);
      BOOST_ERROR("accepted: " << text);
    } catch (const std::invalid_argument& e) {
      BOOST_TEST(std::string(e.what()).find(reason) != std::string::npos, e.what());
    }
  };
  std::string bad_sum = good;
  bad_sum.replace(bad_sum.find("stage C c1 1"), 12, "stage C c1 0.9");
  refuses(bad_sum, "sum to");
  std::string not_palindrome = good;
  not_palindrome.replace(not_palindrome.rfind("stage A a1 0.5"), 14, "stage A a1 0.4");
  not_palindrome.replace(not_palindrome.find("stage A a1 0.5"), 14, "stage A a1 0.6");
  refuses(not_palindrome, "symmetric");
  std::string nan_value = good;
  nan_value.replace(nan_value.find("stage C c1 1"), 12, "stage C c1 nan");
  refuses(nan_value, "not a finite decimal");
  refuses("format_version 2\n", "not supported");
  refuses(good + "colour blue\n", "unknown key");
  std::string wrong_letter = good;
  wrong_letter.replace(wrong_letter.find("stage C c1 1"), 12, "stage D c1 1");
  refuses(wrong_letter, "not in the ABC splitting");
  std::string not_the_word = good;
  not_the_word.replace(not_the_word.find("stage C c1 1"), 12, "stage B c1 1");
  refuses(not_the_word, "word says");
}

namespace {
const std::string leapfrog =
    "format_version 1\nname t\nsplit ABC\nword ABCBA\npermutation ABC\norder 2\nsymmetric true\nstages 5\n"
    "stage A a1 0.5\nstage B b1 0.5\nstage C c1 1\nstage B b1 0.5\nstage A a1 0.5\n";

std::string with_crlf(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return out;
}

std::string refusal(const std::string& text) {
  try {
    parse_scheme_table(text);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(crlf_line_endings_and_a_byte_order_mark_are_accepted) {
  const auto lf = parse_scheme_table(leapfrog);
  BOOST_TEST((parse_scheme_table(with_crlf(leapfrog)) == lf));
  BOOST_TEST((parse_scheme_table("\xEF\xBB\xBF" + leapfrog) == lf));
  BOOST_TEST((parse_scheme_table("\xEF\xBB\xBF" + with_crlf(leapfrog)) == lf));
  BOOST_TEST((parse_scheme_table("  # indented comment\n\t\n" + leapfrog) == lf));  // blank lines of blanks
  BOOST_TEST(lf.name == "t");
  BOOST_TEST(lf.stages[2].value == "1");
  // every reference table, written with CRLF, reads back unchanged
  for (const auto& name : reference_scheme_names()) {
    const auto t = *reference_scheme(name + ":CAB");
    BOOST_TEST((parse_scheme_table(with_crlf(format_scheme_table(t))) == t), name);
  }
}

BOOST_AUTO_TEST_CASE(repeated_keys_and_strict_decimals_are_refused) {
  BOOST_TEST(refusal(leapfrog + "word ABCBA\n").find("given twice") != std::string::npos);
  for (const char* bad : {"0x1p-1", "inf", "1e5000", "0.5.1", "0.5e", ".", "+"}) {
    std::string t = leapfrog;
    t.replace(t.find("stage A a1 0.5"), 14, std::string("stage A a1 ") + bad);
    BOOST_TEST(refusal(t).find("not a finite decimal") != std::string::npos, bad);
  }
  std::string ctrl = leapfrog;
  ctrl.replace(ctrl.find("split ABC"), 9, "split A\x01" "C");
  const auto m = refusal(ctrl);
  BOOST_TEST(m.find("\\x01") != std::string::npos, m);
  BOOST_TEST(m.find('\x01') == std::string::npos, m);
}

BOOST_AUTO_TEST_CASE(first_order_tolerance_grows_with_stages_and_sizes) {
  // Σ c = 1 to n·ε·Σ|c| (ε = DBL_EPSILON): A has 2 stages of 0.5 → tolerance 2ε; C one stage of 1 → ε.
  auto with_a = [](const std::string& a) {
    std::string t = leapfrog;
    t.replace(t.find("stage A a1 0.5"), 14, "stage A a1 " + a);
    t.replace(t.rfind("stage A a1 0.5"), 14, "stage A a1 " + a);
    return t;
  };
  const long double eps = DBL_EPSILON;
  auto text = [](long double x) {
    std::ostringstream s;
    s.precision(30);
    s << x;
    return s.str();
  };
  BOOST_TEST(refusal(with_a(text(0.5L + 0.4L * eps))).empty());         // off by 0.8ε ≤ 2ε
  BOOST_TEST(refusal(with_a(text(0.5L + 1.5L * eps))).find("sum to") != std::string::npos);  // 3ε > 2ε
  // large coefficients of both signs: Σ|c| = 41, so 2·ε·41 (1.8e-14) is allowed, far beyond 1e-15
  const std::string big =
      "format_version 1\nsplit RS\nword RSRSR\nsymmetric true\nstage R a1 10.25\nstage S b1 0.5\n"
      "stage R a2 -19.5\nstage S b1 0.5\nstage R a1 10.25\n";
  BOOST_TEST(refusal(big).empty());
  std::string big_off = big;
  big_off.replace(big_off.find("-19.5"), 5, text(-19.5L + 1e-14L));
  BOOST_TEST(refusal(big_off).empty(), refusal(big_off));  // 1e-14 ≤ 3·ε·40 = 2.7e-14
  big_off = big;
  big_off.replace(big_off.find("-19.5"), 5, text(-19.5L + 1e-13L));
  BOOST_TEST(refusal(big_off).find("sum to") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(written_tables_parse_to_themselves) {
  for (const auto& name : reference_scheme_names())
    for (const char* p : {"ABC", "BAC", "CBA"}) {
      const auto t = *reference_scheme(name + ":" + p);
      const auto back = parse_scheme_table(format_scheme_table(t));
      BOOST_TEST((back == t), name << ":" << p);
    }
  auto t = parse_scheme_table(leapfrog + "inertia 10220/29376 19187/29376 1\nsource hand\n");
  BOOST_TEST((parse_scheme_table(format_scheme_table(t)) == t));
  BOOST_TEST(refusal(leapfrog + "inertia 1 2\n").find("three positive numbers") != std::string::npos);
  BOOST_TEST(refusal(leapfrog + "inertia 1 -2 3\n").find("three positive numbers") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_recorded_body_is_compared_scale_free) {
  const auto water = parse_scheme_table(leapfrog + "inertia 2555/7344 19187/29376 1\n");
  using arr = std::array<std::string_view, 3>;
  // the same ratios in other units and notations (10220/29376 = 2555/7344), exactly
  BOOST_TEST((same_body(water, arr{"10220/29376", "19187/29376", "1"}) == body_match::same));
  BOOST_TEST((same_body(water, arr{"10220", "19187", "29376"}) == body_match::same));
  BOOST_TEST((same_body(water, arr{"1.0220e4", "19.187e3", "2.9376e+4"}) == body_match::same));
  BOOST_TEST((same_body(water, arr{"10220e-300", "19187e-300", "29376e-300"}) == body_match::same));
  // one unit in the last of 40 digits is another body
  BOOST_TEST((same_body(water, arr{"10220.00000000000000000000000000000000001", "19187", "29376"}) == body_match::different));
  BOOST_TEST((same_body(water, arr{"19187", "10220", "29376"}) == body_match::different));
  BOOST_CHECK_THROW(same_body(water, arr{"0", "1", "1"}), std::invalid_argument);
  BOOST_CHECK_THROW(same_body(water, arr{"x", "1", "1"}), std::invalid_argument);
  // in double: ratios to 1e-12 relative
  const double i1 = 10220.0 / 29376, i2 = 19187.0 / 29376;
  BOOST_TEST((same_body(water, std::array<double, 3>{i1, i2, 1}) == body_match::same));
  BOOST_TEST((same_body(water, std::array<double, 3>{i1 * 3e150, i2 * 3e150, 3e150}) == body_match::same));
  BOOST_TEST((same_body(water, std::array<double, 3>{i1 * (1 + 1e-13), i2, 1}) == body_match::same));
  BOOST_TEST((same_body(water, std::array<double, 3>{i1 * (1 + 1e-11), i2, 1}) == body_match::different));
  BOOST_CHECK_THROW(same_body(water, std::array<double, 3>{i1, std::nan(""), 1}), std::invalid_argument);
  // a reference scheme records no body
  BOOST_TEST((same_body(*reference_scheme("ABCBA2"), std::array<double, 3>{1, 2, 3}) == body_match::unrecorded));
}

BOOST_AUTO_TEST_SUITE_END()  // scheme_table_test
