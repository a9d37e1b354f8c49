// Scheme words: coefficient naming and first-order conditions as in the paper (eqs. 44, 50,
// 55–57, 67, 71), permutations, and refusals.
#include <boost/test/unit_test.hpp>

#include <string>
#include <utility>
#include <vector>

#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/bch/scheme_word.hpp"

BOOST_AUTO_TEST_SUITE(scheme_word_test)

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
  const auto l2 = layout_scheme("ABCABC", splitting::abc);
  BOOST_TEST(names(l2) == "a1 b1 c1 a2 b2 c2");
  BOOST_TEST((l2.free_coefficients == std::vector<std::string>{"a1", "b1", "c1"}));
  const auto l3 = layout_scheme("RSRS", splitting::rs);
  BOOST_TEST(names(l3) == "a1 b1 a2 b2");
  BOOST_TEST((l3.free_coefficients == std::vector<std::string>{"a1", "b1"}));
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

namespace {
// The reason of a refusal, or "" when the word is accepted.
std::string refusal(std::string_view word, splitting split) {
  try {
    layout_scheme(word, split);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_part_that_never_acts_is_refused) {
  // H = A + B + C (or R + S): a word missing a part would silently drop it from the flow
  for (const auto& [word, missing] : std::vector<std::pair<std::string, std::string>>{
           {"ABA", "part C"}, {"ABAB", "part C"}, {"ACA", "part B"}, {"BCB", "part A"}, {"A", "part B"}, {"CCCCC", "part A"}})
    BOOST_TEST(refusal(word, splitting::abc).find(missing + " never acts") != std::string::npos, word);
  BOOST_TEST(refusal("RRR", splitting::rs).find("part S never acts") != std::string::npos);
  BOOST_TEST(refusal("S", splitting::rs).find("part R never acts") != std::string::npos);
  // every named scheme has every part, in every permutation
  for (const auto& n : named_schemes())
    for (const auto& p : permutation_names()) BOOST_CHECK_NO_THROW(layout_scheme(n.word, n.split, p));
}

BOOST_AUTO_TEST_CASE(word_length_is_limited) {
  auto palindrome = [](std::size_t n) {  // ABCB ABCB … mirrored, n letters
    std::string half;
    for (std::size_t i = 0; i < (n + 1) / 2; ++i) half += "ABCB"[i % 4];
    std::string w = half;
    for (std::size_t i = n / 2; i-- > 0;) w += half[i];
    return w;
  };
  BOOST_TEST(palindrome(max_word_length).size() == max_word_length);
  const auto l = layout_scheme(palindrome(max_word_length), splitting::abc);
  BOOST_TEST(l.symmetric);
  BOOST_TEST(l.stages.size() == max_word_length);
  const auto too_long = refusal(palindrome(max_word_length + 1), splitting::abc);
  BOOST_TEST(too_long.find("at most " + std::to_string(max_word_length)) != std::string::npos, too_long);
  BOOST_TEST(refusal(std::string(100000, 'R'), splitting::rs).find("at most") != std::string::npos);
  // a control byte is shown, not printed raw
  const auto bad = refusal("AB\nC", splitting::abc);
  BOOST_TEST(bad.find('\n') == std::string::npos, bad);
  BOOST_TEST(bad.find("\\x0A") != std::string::npos, bad);
}

BOOST_AUTO_TEST_CASE(coefficient_values_are_parsed_exactly) {
  const auto v = parse_coefficient_values("a1=1/6,b1=0.25,c12=-3e-2");
  BOOST_REQUIRE(v.size() == 3u);
  BOOST_TEST(v[0].first == "a1");
  BOOST_TEST((v[0].second == cln::cl_RA(1) / 6));
  BOOST_TEST((v[1].second == cln::cl_RA(1) / 4));
  BOOST_TEST(v[2].first == "c12");
  BOOST_TEST((v[2].second == cln::cl_RA(-3) / 100));
  BOOST_TEST(parse_coefficient_values("").empty());
  auto reason = [](const char* text) {
    try {
      parse_coefficient_values(text);
      return std::string();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
  };
  BOOST_TEST(reason("a1=1,a1=2").find("given twice") != std::string::npos);
  BOOST_TEST(reason("a1").find("name=value") != std::string::npos);
  BOOST_TEST(reason("a1=1,").find("name=value") != std::string::npos);
  BOOST_TEST(reason("A1=1").find("not a coefficient name") != std::string::npos);
  BOOST_TEST(reason("a0=1").find("not a coefficient name") != std::string::npos);
  BOOST_TEST(reason("a=1").find("not a coefficient name") != std::string::npos);
  BOOST_TEST(reason("a1=nan").find("not a finite number") != std::string::npos);
  BOOST_TEST(reason("a1=1e999").find("beyond the supported range") != std::string::npos);
  BOOST_TEST(reason("a1=1/0").find("zero denominator") != std::string::npos);
}

namespace {
std::string remainder_refusal(const std::string& word, int order) {
  remainder_request r;
  r.scheme = word;
  r.order = order;
  r.inertia = rotlie::lie::parse_moments("water");
  try {
    compute_remainder(r);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}
std::string cycled(const std::string& letters, std::size_t n) {
  std::string w;
  for (std::size_t i = 0; i < n; ++i) w += letters[i % letters.size()];
  return w;
}
}  // namespace

BOOST_AUTO_TEST_CASE(remainder_words_are_limited_by_order) {
  // the stated budget: every named scheme fits at every order, the 11-stage P family at order 9
  for (int order = 1; order <= max_remainder_order; ++order) {
    BOOST_TEST(max_remainder_stages(order, true) >= 11u);
    BOOST_TEST(max_remainder_stages(order, true) <= max_word_length);
    BOOST_TEST(max_remainder_stages(order, false) <= max_remainder_stages(order, true));
    if (order > 1) BOOST_TEST(max_remainder_stages(order, false) <= max_remainder_stages(order - 1, false));
  }
  // one stage beyond the budget is refused at once with the limit in the message
  const auto nonsym = cycled("ABC", max_remainder_stages(5, false) + 1);
  BOOST_TEST(remainder_refusal(nonsym, 5).find("at most " + std::to_string(max_remainder_stages(5, false))) != std::string::npos);
  const auto p = "ABCBABCBABCBA";  // a 13-stage palindrome
  BOOST_TEST(remainder_refusal(p, 9).find("at most 11 stages") != std::string::npos);
  BOOST_TEST(remainder_refusal(cycled("ABC", 26), 1).find("at most 25") != std::string::npos);
  BOOST_TEST(remainder_refusal("ABA", 3).find("part C never acts") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_longest_word_keeps_the_hamiltonian_at_first_order) {
  // H_R1 = H = A + B + C when the first-order conditions hold, for a word at the length limit
  remainder_request r;
  r.scheme = cycled("ABC", max_word_length);
  r.order = 1;
  r.inertia = rotlie::lie::parse_moments("1,2,2");
  const auto result = compute_remainder(r);
  BOOST_TEST(result.layout.stages.size() == max_word_length);
  const auto& I = r.inertia->I;
  const std::array<cln::cl_RA, 3> w{cln::recip(I[0]), cln::recip(I[1]), cln::recip(I[2])};
  const auto h = rational_part_hamiltonian('A', splitting::abc, "ABC", w) + rational_part_hamiltonian('B', splitting::abc, "ABC", w) +
                 rational_part_hamiltonian('C', splitting::abc, "ABC", w);
  BOOST_REQUIRE(result.k.remainder.size() >= 2u);
  for (const auto& [m, c] : h.terms()) {
    const GiNaC::ex got = result.k.remainder[1].coefficient(m);
    const GiNaC::ex want = GiNaC::numeric(cln::cl_N(c));
    BOOST_TEST(GiNaC::ex(got - want).expand().is_zero());
  }
  BOOST_TEST(result.k.remainder[1].size() == h.size());
}

BOOST_AUTO_TEST_SUITE_END()  // scheme_word_test
