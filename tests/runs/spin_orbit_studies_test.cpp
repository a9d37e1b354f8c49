// The spin–orbit report's studies (runs/hyperion_study, spin_islands_study) against what they must give:
// the e-folding rate of an exact exponential; Hyperion's island widths against Cayley's H written out here,
// its resonant orbits turning p times per orbit, the 1:1 orbit elliptic and both 3:2 hyperbolic; and the
// surface of section's summary regular far above the chaotic zone.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "rotlie/runs/hyperion_study.hpp"
#include "rotlie/runs/spin_islands_study.hpp"

BOOST_AUTO_TEST_SUITE(spin_orbit_studies_test)

using namespace rotlie;

BOOST_AUTO_TEST_CASE(the_e_folding_rate_of_an_exponential) {
  std::vector<double> x;
  for (int k = 0; k < 60; ++k) x.push_back(1e-7 * std::exp(0.3 * k));
  // first above 1e-5 at k = 16, above 1e-2 at k = 39: the slope of the log between them
  BOOST_TEST(runs::e_folding_rate(x, 1e-5, 1e-2) == 0.3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::isnan(runs::e_folding_rate(std::vector<double>(30, 1e-6), 1e-5, 1e-2)));  // never grows
  x.resize(30);  // stops below 1e-2
  BOOST_TEST(std::isnan(runs::e_folding_rate(x, 1e-5, 1e-2)));
}

BOOST_AUTO_TEST_CASE(hyperions_islands) {
  const auto I = runs::spin_moments(runs::spin_body_named("Hyperion"));
  const double e = 0.1, w0 = std::sqrt(3 * (I[1] - I[0]) / I[2]);
  // a coarse grid, few orbits: the grid's verdicts are the report's, not this test's
  const auto is = runs::hyperion_islands(e, 0.45, 10, 50);
  BOOST_TEST(is.omega0 == w0, boost::test_tools::tolerance(1e-15));
  // Cayley's H (WPM 1984) to the order they quote
  const double H[3] = {1 - 2.5 * e * e, 3.5 * e - 123.0 / 16 * e * e * e, 8.5 * e * e};
  BOOST_REQUIRE(is.widths.size() == 3u);
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(is.widths[k].half_width == w0 * std::sqrt(H[k]), boost::test_tools::tolerance(1e-14));
  // Hyperion's 1:1 and 3:2 resonances overlap (Chirikov's criterion above 1), so do 3:2 and 2:1
  BOOST_TEST(is.overlap_1_to_3_2 > 1);
  BOOST_TEST(is.overlap_3_2_to_2 > 1);
  BOOST_REQUIRE(is.orbits.size() == 6u);
  for (const auto& f : is.orbits) {
    BOOST_TEST_MESSAGE("p = " << f.p << " from θ₀ = " << f.theta0 << ": rate " << f.rate << ", turns " << f.turns << ", trace " << f.trace);
    BOOST_TEST(f.found);
    BOOST_TEST(std::abs(f.turns - f.p) < 1e-3);  // an orbit of the p:1 resonance turns p times an orbit
    if (f.p == 1) BOOST_TEST(f.elliptic);
    if (f.p == 1.5) BOOST_TEST(!f.elliptic);
  }
  BOOST_TEST(is.starts == 6);
  BOOST_TEST(static_cast<int>(is.regular_turns.size()) == is.regular);
}

BOOST_AUTO_TEST_CASE(the_section_is_regular_far_above_the_chaotic_zone) {
  // starts at 0.2, 1.6 and 3.0 n, 100 orbits: above about 2.5 n the spin is a regular rotation (WPM 1984)
  const auto s = runs::hyperion_section_study(1.4, 100, 100);
  BOOST_REQUIRE(s.starts.size() == 6u);
  BOOST_REQUIRE(s.section.lyapunov.size() == 6u);
  BOOST_TEST(s.regular_floor == std::log(100.0) / 100, boost::test_tools::tolerance(1e-15));
  for (std::size_t j = 4; j < 6; ++j) BOOST_TEST(s.section.lyapunov[j] < runs::spin_chaos_threshold);
  int chaotic = 0;
  for (const double l : s.section.lyapunov) chaotic += l > runs::spin_chaos_threshold;
  BOOST_TEST(s.chaotic == chaotic);
  BOOST_TEST(s.chaotic_rates[0].size() + s.chaotic_rates[1].size() == static_cast<std::size_t>(chaotic));
  BOOST_TEST(s.lyapunov_time_orbits * s.largest == 1.0, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()  // spin_orbit_studies_test
