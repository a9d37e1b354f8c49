// Dedicated 6th-order schemes (solver/sixth_order_search): the 21-stage ABC palindromes are
// enumerated (2^9 − 1 words in first-appearance naming); a root for water of
// ABABABACABCBACABABABA in the permutation BCA, found by the search and recorded here to 17 digits,
// is refined and polished to 45 digits, its written decimals satisfy every condition of H_R3 and
// H_R5 to 1e-40 of their terms, and as a scheme table it has a fitted slope of 6 ± 0.1 on water in
// float128, falling to 2 on another body.
#define BOOST_TEST_MODULE sixth_order
#include <boost/test/unit_test.hpp>

#include "model_support.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/sixth_order_search.hpp"

using namespace rotlie;
using test::quad;

namespace {

double slope(const schemes::scheme_table& t, const models::vec3<quad>& I) {
  return models::measure_order<quad>(t, I, test::initial_state<quad>({quad(1), quad(1), quad(1)}), quad(1), 4, 8, 5).slope;
}

}  // namespace

BOOST_AUTO_TEST_CASE(palindromes_are_enumerated_once_each) {
  BOOST_TEST(solver::palindromic_words(21, bch::splitting::abc).size() == 511u);  // 2^9 first halves, less ABABABABABA
  BOOST_TEST(solver::palindromic_words(19, bch::splitting::rs).size() == 1u);
  BOOST_TEST(solver::palindromic_words(5, bch::splitting::abc) == std::vector<std::string>{"ABCBA"});
  BOOST_TEST(solver::palindromic_words(20, bch::splitting::abc).empty());  // the middle letter would repeat
  for (const auto& w : solver::palindromic_words(9, bch::splitting::abc)) BOOST_TEST(bch::layout_scheme(w, bch::splitting::abc).symmetric);
}

BOOST_AUTO_TEST_CASE(a_water_root_is_a_sixth_order_scheme) {
  const auto body = lie::parse_moments("water");
  const auto layout = bch::layout_scheme("ABABABACABCBACABABABA", bch::splitting::abc, "BCA");
  const auto s = solver::sixth_order_conditions(layout, body);
  BOOST_TEST(s.free_count() == 8);
  BOOST_TEST(s.conditions.size() == 8u);      // dim L3 + dim L5 = 2 + 6
  BOOST_TEST(s.all_conditions.size() == 10u); // Theorem 1's 3 + 7 monomials
  const std::vector<long double> start{0.33718722911498938L, -0.13815663917773258L, -0.54980917836124354L, -0.92470349720697986L,
                                       -0.052954494390111906L, 0.69833209477840996L, 0.65398715803888641L, 0.13496378909361112L};
  const auto x = solver::polished_root(s, start, 45);
  BOOST_TEST(cln::double_approx(solver::sixth_order_residual(s, x, 45)) < 1e-40);
  const auto text = solver::sixth_order_table_text(s, x, 45, body, "D6:ABABABACABCBACABABABA:BCA", "test");
  const auto table = schemes::parse_scheme_table(text);
  BOOST_TEST(table.order == 6);
  BOOST_TEST(std::abs(slope(table, test::water_moments<quad>()) - 6) < 0.1);
  BOOST_TEST(slope(table, {quad(1) / 2, quad(4) / 5, quad(1)}) < 4.2);  // dedicated: another body loses the order
  // The same start perturbed at 1e-6 still polishes to the same root (a regular root: its basin).
  auto nudged = start;
  for (auto& v : nudged) v *= 1 + 1e-6L;
  BOOST_TEST((solver::polished_root(s, nudged, 45) == x));
}
