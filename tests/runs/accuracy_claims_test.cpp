// The paper's seven accuracy claims (LV section 4), each a ratio of two protocol curves computed
// as the report computes them (runs::compute_accuracy_curves: the composition engine, the one
// integrate loop, errors in long double, h = 2^-1 … 2^-10), checked against the paper's figure.
// Tolerance 5 %: the paper prints its ratios to two significant figures (up to 3.3 % of rounding,
// 6 % for its "8×"), and the report's own check allows 20 %.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "rotlie/runs/accuracy_curves.hpp"

BOOST_AUTO_TEST_SUITE(accuracy_claims_test)

using namespace rotlie;

BOOST_AUTO_TEST_CASE(the_papers_seven_accuracy_claims_hold) {
  const auto curves = runs::compute_accuracy_curves(10);
  BOOST_TEST_REQUIRE(curves.claims.size() == 7u);
  for (const auto& c : curves.claims) {
    const double ours = c.at_equal_reduced_step();
    BOOST_TEST_MESSAGE(c.text << ": LV " << c.paper << "×, ours " << ours << "× (" << c.worse.name << " vs "
                              << c.better.name << ")");
    BOOST_TEST(std::abs(ours / c.paper - 1) <= 0.05, c.text << ": ours " << ours << "×, LV " << c.paper << "×");
    // both curves are 4th order where the claim compares them
    BOOST_TEST(std::abs(c.worse.slope - 4) < 0.1, c.worse.name << " slope " << c.worse.slope);
    BOOST_TEST(std::abs(c.better.slope - 4) < 0.1, c.better.name << " slope " << c.better.slope);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // accuracy_claims_test
