// Two free parameters at order 4 (solver/two_parameter): the families' words; the search and polish
// checked on P1 BAC (one free parameter) against the exact elimination of dedicated_schemes (the
// global minimum of ‖H_R5‖ on the curve is the smallest of all its critical points, which the exact
// solver lists); the best water schemes found (RS and ABC), recorded to 12 digits and polished to
// 45: order 4 certified at the written decimals, projected gradient vanishing, a local minimum,
// ‖H_R5‖ recomputed by the numeric expansion, and slope 4 ± 0.1 on water in float128.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model_support.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/two_parameter.hpp"

BOOST_AUTO_TEST_SUITE(two_parameter_test)

using namespace rotlie;
using rotlie::quad;

namespace {

constexpr int digits = 45;

double slope(const schemes::scheme_table& t, const models::vec3<quad>& I) {
  return models::measure_order<quad>(t, I, test::initial_state<quad>({quad(1), quad(1), quad(1)}), quad(1), 3, 8, 4).slope;
}

// ‖H_R5‖ by the numeric expansion (double), independent of the exact polynomial the search minimises.
double numeric_remainder(const solver::two_parameter_system& s, const solver::certified_minimum& m) {
  std::map<std::string, double> values;
  for (const auto& [name, v] : m.values) values[name] = cln::double_approx(v);
  const std::array<cln::cl_RA, 3> w{cln::recip(s.body.I[0]), cln::recip(s.body.I[1]), cln::cl_RA(1)};
  const auto h = bch::compute_numeric_modified_hamiltonian(s.layout, w, values, 5);
  double sum = 0;
  for (const auto& [monomial, c] : h[5].terms()) sum += c * c;
  return std::sqrt(sum);
}

// Polishes a recorded minimum and checks every certificate; returns the polished minimum.
solver::certified_minimum check_minimum(const solver::two_parameter_system& s, const std::vector<long double>& x) {
  solver::local_minimum start;
  start.x = x;
  const auto m = solver::polish_minimum(s, start, digits);
  BOOST_TEST(m.order == 4);
  BOOST_TEST(cln::double_approx(m.order_residual) < 1e-40);
  BOOST_TEST(cln::double_approx(m.projected_gradient) < 1e-40);
  BOOST_TEST(m.is_minimum());
  BOOST_TEST(std::abs(numeric_remainder(s, m) / m.remainder - 1) < 1e-9);
  // A start off by 1e-7 polishes to the same decimals: a regular critical point.
  auto nudged = x;
  for (auto& v : nudged) v *= 1 + 1e-7L;
  start.x = nudged;
  BOOST_TEST((solver::polish_minimum(s, start, digits).x == m.x));
  return m;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_families_have_four_free_coefficients) {
  const auto abc = solver::two_parameter_words(bch::splitting::abc);
  BOOST_TEST(abc.size() == 31u);  // first halves AB + 5 letters, none repeated: 2^5, less ABABABA (no C)
  for (const auto& w : abc) BOOST_TEST(bch::layout_scheme(w, bch::splitting::abc).free_coefficients.size() == 4u);
  for (const auto& w : solver::two_parameter_words(bch::splitting::rs))
    BOOST_TEST(bch::layout_scheme(w, bch::splitting::rs).free_coefficients.size() == 4u);
  BOOST_CHECK_THROW(solver::two_parameter_conditions(bch::layout_scheme("ABABCBABA", bch::splitting::abc), lie::parse_moments("water")),
                    std::invalid_argument);  // N1: two free coefficients
}

BOOST_AUTO_TEST_CASE(the_search_finds_the_exact_solvers_minimum_on_a_curve) {
  const auto body = lie::parse_moments("water");
  const auto exact = solver::solve_dedicated(body, {"P1"}, {"BAC"}, 40);
  const auto& best = exact.solutions.front();  // sorted by ‖H_R5‖: the smallest critical value on the curve
  const auto s = solver::two_parameter_conditions(best.layout, body);
  solver::minimum_search_options o;
  o.starts = 40;
  const auto found = solver::search_minima(s, o);
  BOOST_REQUIRE(!found.minima.empty());
  const auto m = solver::polish_minimum(s, found.minima.front(), 40);
  BOOST_TEST(m.is_minimum());
  for (const auto& [name, v] : best.coefficients) BOOST_TEST(cln::double_approx(cln::abs(m.values.at(name) - v)) < 1e-35);
  BOOST_TEST(std::abs(m.remainder / best.analytic_remainder - 1) < 1e-12);
}

BOOST_AUTO_TEST_CASE(the_best_rs_water_scheme_is_a_certified_fourth_order_minimum) {
  const auto body = lie::parse_moments("water");
  const auto s = solver::two_parameter_conditions(bch::layout_scheme("RSRSRSRSRSR", bch::splitting::rs, "CBA"), body);
  const auto m = check_minimum(s, {0.0870783524259L, 0.251627935220L, 0.540096652858L, -0.0764816771366L});
  BOOST_TEST(std::abs(m.remainder - 1.75392e-4) < 1e-9);
  // R ↔ S under the exchange of the first and third axes (S's G²/(2 I2) commutes with everything):
  // SRSRSRSRSRS in ABC with the same coefficients stage by stage is the same scheme, same ‖H_R5‖.
  const auto swapped = solver::two_parameter_conditions(bch::layout_scheme("SRSRSRSRSRS", bch::splitting::rs, "ABC"), body);
  BOOST_TEST(std::abs(std::sqrt(cln::double_approx(swapped.norm_squared(m.x))) / m.remainder - 1) < 1e-12);
  const auto table = schemes::parse_scheme_table(solver::two_parameter_table_text(s, m, digits, body, "QRS:RSRSRSRSRSR:CBA", "test"));
  BOOST_TEST(table.order == 4);
  BOOST_TEST(std::abs(slope(table, test::water_moments<quad>()) - 4) < 0.1);
  // Two generators: dim L3 of the free Lie algebra is 2 as well, so H_R3 = 0 is the general order-4
  // condition and the scheme keeps its order on every body; only the minimised ‖H_R5‖ is water's.
  BOOST_TEST(std::abs(slope(table, {quad(1) / 2, quad(4) / 5, quad(1)}) - 4) < 0.1);
}

BOOST_AUTO_TEST_CASE(the_best_abc_water_scheme_is_a_certified_fourth_order_minimum) {
  const auto body = lie::parse_moments("water");
  const auto s = solver::two_parameter_conditions(bch::layout_scheme("ABACBABABCABA", bch::splitting::abc, "ABC"), body);
  const auto m = check_minimum(s, {0.105180100593L, 0.371235036787L, 0.0390959635858L, 0.0983579629960L});
  BOOST_TEST(std::abs(m.remainder - 5.87919e-4) < 1e-9);
  BOOST_TEST(m.values.at("c1") == cln::cl_RA(1) / 2);  // C acts twice: the first-order condition alone fixes it
  const auto table = schemes::parse_scheme_table(solver::two_parameter_table_text(s, m, digits, body, "Q:ABACBABABCABA:ABC", "test"));
  BOOST_TEST(std::abs(slope(table, test::water_moments<quad>()) - 4) < 0.1);
  BOOST_TEST(slope(table, {quad(1) / 2, quad(4) / 5, quad(1)}) < 3);  // dedicated: another body loses the order
}

BOOST_AUTO_TEST_SUITE_END()  // two_parameter_test
