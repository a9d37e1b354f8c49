// Scheme words: coefficient naming and first-order conditions as in the paper (eqs. 44, 50,
// 55–57, 67, 71), permutations, and refusals.
#define BOOST_TEST_MODULE scheme_word
#include <boost/test/unit_test.hpp>

#include "rotlie/bch/scheme_word.hpp"

using namespace rotlie::bch;

namespace {
std::string names(const scheme_layout& l) {
  std::string s;
  for (const auto& st : l.stages) s += (s.empty() ? "" : " ") + st.coefficient;
  return s;
}
GiNaC::ex value(const coefficient_symbols& c, const std::string& name) { return c.value.at(name); }
}  // namespace

BOOST_AUTO_TEST_CASE(n4_naming_and_first_order_conditions_eqs_55_to_57) {
  const auto l = layout_scheme("ABCABACBA", splitting::abc);
  BOOST_TEST(names(l) == "a1 b1 c1 a2 b2 a2 c1 b1 a1");
  BOOST_TEST(l.symmetric);
  BOOST_TEST((l.free_coefficients == std::vector<std::string>{"a1", "b1"}));
  const auto c = make_coefficients(l);
  const GiNaC::ex a1 = c.free.at("a1"), b1 = c.free.at("b1");
  BOOST_TEST((value(c, "a2") - (GiNaC::ex(1) / 2 - a1)).expand().is_zero());
  BOOST_TEST((value(c, "b2") - (1 - 2 * b1)).expand().is_zero());
  BOOST_TEST((value(c, "c1") - GiNaC::ex(1) / 2).expand().is_zero());
}

BOOST_AUTO_TEST_CASE(rs_words_eqs_44_50_67) {
  BOOST_TEST(names(layout_scheme("RSRSRSR", splitting::rs)) == "a1 b1 a2 b2 a2 b1 a1");
  BOOST_TEST(names(layout_scheme("SRSRSRS", splitting::rs)) == "a1 b1 a2 b2 a2 b1 a1");  // S gets a (eq. 50)
  const auto r = layout_scheme("RSRSRSRSR", splitting::rs);
  const auto c = make_coefficients(r);
  const GiNaC::ex a1 = c.free.at("a1"), a2 = c.free.at("a2"), b1 = c.free.at("b1");
  BOOST_TEST((value(c, "a3") - (1 - 2 * (a1 + a2))).expand().is_zero());           // eq. (67)
  BOOST_TEST((value(c, "b2") - (GiNaC::ex(1) / 2 - b1)).expand().is_zero());
}

BOOST_AUTO_TEST_CASE(p1_eq_71_and_raw_word_naming) {
  const auto c = make_coefficients(layout_scheme("ABABACABABA", splitting::abc));
  const GiNaC::ex a1 = c.free.at("a1"), a2 = c.free.at("a2"), b1 = c.free.at("b1");
  BOOST_TEST((value(c, "a3") - (GiNaC::ex(1) / 2 - a1 - a2)).expand().is_zero());
  BOOST_TEST((value(c, "b2") - (GiNaC::ex(1) / 2 - b1)).expand().is_zero());
  BOOST_TEST((value(c, "c1") - 1).expand().is_zero());
  // ACBCBCBCA: A gets a, C gets b, B gets c (order of first appearance)
  BOOST_TEST(names(layout_scheme("ACBCBCBCA", splitting::abc)) == "a1 b1 c1 b2 c2 b2 c1 b1 a1");
}

BOOST_AUTO_TEST_CASE(permutation_substitutes_letters_keeping_names) {
  const auto l = layout_scheme("ABCABACBA", splitting::abc, "CAB");
  BOOST_TEST(l.permuted == "CABCACBAC");
  BOOST_TEST(names(l) == "a1 b1 c1 a2 b2 a2 c1 b1 a1");
  BOOST_TEST(layout_scheme("ABACACABA", splitting::abc, "BAC").permuted == "BABCBCBAB");  // eq. (73)
}

BOOST_AUTO_TEST_CASE(non_symmetric_words_index_every_stage) {
  const auto l = layout_scheme("ABC", splitting::abc);
  BOOST_TEST(!l.symmetric);
  BOOST_TEST(names(l) == "a1 b1 c1");
  BOOST_TEST(l.free_coefficients.empty());
  const auto l2 = layout_scheme("ABAB", splitting::abc);
  BOOST_TEST(names(l2) == "a1 b1 a2 b2");
  BOOST_TEST((l2.free_coefficients == std::vector<std::string>{"a1", "b1"}));
}

BOOST_AUTO_TEST_CASE(bad_words_and_permutations_are_refused) {
  BOOST_CHECK_THROW(layout_scheme("", splitting::abc), std::invalid_argument);
  BOOST_CHECK_THROW(layout_scheme("ABD", splitting::abc), std::invalid_argument);
  BOOST_CHECK_THROW(layout_scheme("RSA", splitting::rs), std::invalid_argument);
  BOOST_CHECK_THROW(layout_scheme("ABA", splitting::abc, "ABD"), std::invalid_argument);
  BOOST_CHECK_THROW(layout_scheme("ABA", splitting::abc, "AAB"), std::invalid_argument);
  BOOST_TEST(find_named_scheme("N4")->word == "ABCABACBA");
  BOOST_TEST(find_named_scheme("P15")->word == "ABCBCBCBCBA");
  BOOST_TEST(!find_named_scheme("N8").has_value());
}
