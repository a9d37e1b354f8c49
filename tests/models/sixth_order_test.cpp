// Dedicated 6th-order schemes (solver/sixth_order_search): the 21-stage ABC palindromes are
// enumerated (2^9 − 1 words in first-appearance naming); a root for water of
// ABABABACABCBACABABABA in the permutation BCA, found by the search and recorded here to 17 digits,
// is refined and polished to 45 digits, its written decimals satisfy every condition of H_R3 and
// H_R5 to 1e-40 of their terms, and as a scheme table it has a fitted slope of 6 ± 0.1 on water in
// float128, falling to 2 on another body.
#include <boost/test/unit_test.hpp>

#include "model_support.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/sixth_order_scan.hpp"
#include "rotlie/solver/sixth_order_search.hpp"

#include <sstream>

BOOST_AUTO_TEST_SUITE(sixth_order_test)

using namespace rotlie;
using rotlie::quad;

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

BOOST_AUTO_TEST_CASE(the_best_water_root_of_the_broad_scan_is_a_sixth_order_scheme) {
  // ‖H_R7‖ 3.1e-4, the smallest of the 40-start scan of all 3 066 systems; recorded to 17 digits.
  const auto body = lie::parse_moments("water");
  const auto s = solver::sixth_order_conditions(bch::layout_scheme("ABACBCBCACACACBCBCABA", bch::splitting::abc, "ABC"), body);
  const std::vector<long double> start{0.031142449544525205L, 0.049081986854657256L, 0.17053382532122619L, 0.047546598888505889L,
                                       0.40122423124259771L,  0.18949540247349139L,  -0.013160511063164137L, 0.099453077558223607L};
  const auto x = solver::polished_root(s, start, 45);
  BOOST_TEST(cln::double_approx(solver::sixth_order_residual(s, x, 45)) < 1e-40);
  BOOST_TEST(solver::jacobian_condition_ratio(s, start) > 1e-6);
  const auto table = schemes::parse_scheme_table(solver::sixth_order_table_text(s, x, 45, body, "D6 best", "test"));
  BOOST_TEST(std::abs(slope(table, test::water_moments<quad>()) - 6) < 0.1);
  BOOST_TEST(slope(table, {quad(1) / 2, quad(4) / 5, quad(1)}) < 4.2);
}

BOOST_AUTO_TEST_CASE(the_spherical_top_has_isolated_sixth_order_roots) {
  // A root found by `rotlie sixth --inertia sphere --all --starts 20`, recorded to 17 digits.
  const auto body = lie::parse_moments("sphere");
  const auto s = solver::sixth_order_conditions(bch::layout_scheme("ABCBCABCBACABCBACBCBA", bch::splitting::abc, "ABC"), body);
  const std::vector<long double> start{0.23112782163141612L, 0.039402161526535147L, 0.25645803827100588L, 0.059492632976461797L,
                                       0.016101596511745617L, 0.22257907548455916L, 0.031059072594541867L, 0.081653941347874376L};
  const auto x = solver::polished_root(s, start, 45);
  BOOST_TEST(cln::double_approx(solver::sixth_order_residual(s, x, 45)) < 1e-40);
  // Regular: the scaled Jacobian's smallest singular value is far from round-off (a family would give ~1e-16).
  BOOST_TEST(solver::jacobian_condition_ratio(s, start) > 1e-6);
  const auto table = schemes::parse_scheme_table(solver::sixth_order_table_text(s, x, 45, body, "D6 sphere", "test"));
  BOOST_TEST(std::abs(slope(table, {quad(1), quad(1), quad(1)}) - 6) < 0.1);
  BOOST_TEST(slope(table, test::water_moments<quad>()) < 4.2);
}

BOOST_AUTO_TEST_CASE(a_resumed_scan_equals_an_uninterrupted_one) {
  const auto body = lie::parse_moments("water");
  const auto s = solver::sixth_order_conditions(bch::layout_scheme("ABABABACABCBACABABABA", bch::splitting::abc, "BCA"), body);
  solver::scan_rule rule;
  rule.budget = 200;
  solver::scanned_system whole{"ABABABACABCBACABABABA", "BCA"}, parts = whole;
  solver::continue_scan(s, whole, rule);
  rule.budget = 90;  // stopped, written, read back, continued
  solver::continue_scan(s, parts, rule);
  std::stringstream state;
  solver::write_scan_state(state, {parts});
  auto back = solver::read_scan_state(state);
  BOOST_TEST_REQUIRE(back.size() == 1u);
  rule.budget = 200;
  solver::continue_scan(s, back[0], rule);
  BOOST_TEST(back[0].starts == whole.starts);
  BOOST_TEST(back[0].converged == whole.converged);
  BOOST_TEST_REQUIRE(back[0].roots.size() == whole.roots.size());
  BOOST_TEST(whole.roots.size() >= 1u);
  for (std::size_t i = 0; i < whole.roots.size(); ++i)
    for (std::size_t k = 0; k < whole.roots[i].x.size(); ++k)
      BOOST_TEST(std::abs(static_cast<double>(back[0].roots[i].x[k] - whole.roots[i].x[k])) < 1e-15);
}

BOOST_AUTO_TEST_CASE(hit_statistics_follow_their_closed_forms) {
  // Roots hit 1, 1, 1, 2, 3 times: N = 8, f1 = 3, f2 = 1; Good–Turing f1/N = 3/8, Chao1 = 5 + 9/2.
  solver::scanned_system r{"W", "ABC", 100, 8, {}};
  for (int hits : {1, 1, 1, 2, 3}) r.roots.push_back({{0.1L * hits}, hits});
  const auto h = solver::statistics_of({r, solver::scanned_system{"V", "ABC", 50, 0, {}}});
  BOOST_TEST(h.systems == 2);
  BOOST_TEST(h.with_roots == 1);
  BOOST_TEST(h.starts == 150);
  BOOST_TEST(h.roots == 5);
  BOOST_TEST(h.unseen == 3.0 / 8);
  BOOST_TEST(h.chao1 == 9.5);
  BOOST_TEST(solver::unseen_mass(r) == 3.0 / 8);
  std::istringstream bad("system W ABC 10 20 0\n");  // more converged than starts
  BOOST_CHECK_THROW(solver::read_scan_state(bad), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // sixth_order_test
