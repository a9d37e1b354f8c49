// Scheme tables on the numeric side: the reference schemes meet the contract (Σ per part = 1,
// palindromes, stage counts and costs of LV section 4 and REFERENCE.md §1.4), their coefficients
// equal the closed forms, permutations substitute letters, and bad tables are refused.
#define BOOST_TEST_MODULE scheme_table
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "rotlie/schemes/reference_schemes.hpp"

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
