// The observers of a free-body run and the one order fit: the two exact references (samples on
// the finest grid, the flow evaluated at each step's time) measure the same run alike; |G| drifts
// by round-off only and the energy error of a second-order scheme falls as h²; the guard stops a
// run at its first non-finite state, and on a threshold, before the observers after it see it;
// the fit's rule keeps exactly the points it names, and measures a closed-form power law exactly.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "model_support.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

BOOST_AUTO_TEST_SUITE(free_body_observers_test)

using namespace rotlie;

namespace {
const auto water = test::water_moments<double>();
const auto start = test::initial_state<double>({1, 1, 1});
}  // namespace

BOOST_AUTO_TEST_CASE(sampled_and_evaluated_references_agree) {
  const auto method = models::free_body_method(*schemes::reference_scheme("RSR4-SS3-Yoshida:CBA"), water);
  const models::exact_samples<double> samples(water, start, 2.0, 9);
  const models::exact_free_body<double> exact(water, start);
  for (int level : {4, 7, 9}) {
    models::sampled_attitude_error<double> sampled(samples, level);
    models::flow_attitude_error<double> evaluated(exact);
    auto s = start;
    const long n = 1L << level;
    BOOST_TEST(models::integrate(method, s, 2.0 / static_cast<double>(n), n, sampled, evaluated) == n);
    BOOST_TEST(sampled.steps() == n);
    BOOST_TEST(std::abs(sampled.mean() - evaluated.mean()) < 1e-14);
    BOOST_TEST(std::abs(sampled.reference_mean() - evaluated.reference_mean()) < 1e-15);
    BOOST_TEST(sampled.mean() > 1e3 * sampled.reference_mean());  // the scheme's error, not the reference's
    BOOST_TEST(sampled.mean() == models::mean_attitude_error(method, start, samples, level));
  }
}

BOOST_AUTO_TEST_CASE(momentum_is_kept_and_the_energy_error_is_second_order) {
  const auto method = models::free_body_method(*schemes::reference_scheme("ABCBA2"), water);
  double previous = 0;
  for (long n : {200L, 400L, 800L}) {
    models::invariant_drift<double> drift(water, start);
    auto s = start;
    models::integrate(method, s, 10.0 / static_cast<double>(n), n, drift);
    BOOST_TEST(drift.momentum_error() < 1e3 * std::numeric_limits<double>::epsilon() * static_cast<double>(n));
    BOOST_TEST(drift.energy_error() > 0.0);
    if (previous > 0) BOOST_TEST(std::abs(std::log2(previous / drift.energy_error()) - 2) < 0.1);  // h² (leapfrog)
    previous = drift.energy_error();
  }
}

BOOST_AUTO_TEST_CASE(the_guard_stops_at_the_first_failing_state) {
  const auto method = models::free_body_method(*schemes::reference_scheme("ABCBA2"), water);
  {  // a NaN step: the first state is not finite; the observer after the guard never sees it
    auto guard = models::stop_unless_finite<double>();
    models::invariant_drift<double> drift(water, start);
    auto s = start;
    BOOST_TEST(models::integrate(method, s, std::nan(""), 50, guard, drift) == 1);
    BOOST_TEST(guard.stopped());
    BOOST_TEST(guard.stopped_at() == 1);
    BOOST_TEST(drift.energy_error() == 0.0);
  }
  {  // a threshold on another observer's figure: the run ends at the first step past it
    models::invariant_drift<double> drift(water, start);
    auto over = models::stop_when([&](const models::body_state<double>&) { return drift.energy_error() > 3e-4; });
    auto s = start;
    const long done = models::integrate(method, s, 0.1, 1000, drift, over);
    BOOST_TEST(over.stopped());
    BOOST_TEST(done == over.stopped_at());
    BOOST_TEST((done > 1 && done < 1000));
    BOOST_TEST(drift.energy_error() > 3e-4);
    // the same run one step shorter never passed the threshold
    models::invariant_drift<double> shorter(water, start);
    auto s2 = start;
    models::integrate(method, s2, 0.1, done - 1, shorter);
    BOOST_TEST(shorter.energy_error() <= 3e-4);
  }
}

BOOST_AUTO_TEST_CASE(the_fit_keeps_the_points_its_rule_names) {
  // error = 3 h^4 down to level 7, then a round-off plateau at 1e-9 (levels 8 … 10); the
  // reference's own estimate is 2e-9 at level 7, so that point is the reference's (< 10 × 2e-9)
  std::vector<models::protocol_point> points;
  for (int level = 1; level <= 10; ++level) {
    const double h = std::ldexp(1.0, -level);
    points.push_back({h, h / 5, level <= 7 ? 3 * std::pow(h, 4) : 1e-9, level == 7 ? 2e-9 : 0.0});
  }
  auto subset = [&](std::initializer_list<int> levels) {
    std::vector<models::protocol_point> out;
    for (int level : levels) out.push_back(points[static_cast<std::size_t>(level - 1)]);
    return out;
  };
  models::fit_rule every;
  every.margin = 0;
  BOOST_TEST(models::fitted_order(points, every) < 3.5);  // the plateau drags the slope down

  models::fit_rule cli;  // the order command's rule: at most four points above the floor, attributable
  cli.at_most = 4;
  cli.floor = 1e-9;
  const double s = models::fitted_order(points, cli);
  BOOST_TEST(std::abs(s - 4) < 1e-12);
  BOOST_TEST(s == models::fitted_order(subset({3, 4, 5, 6}), every));  // exactly those points

  cli.margin = 0;  // level 7 counts again
  BOOST_TEST(models::fitted_order(points, cli) == models::fitted_order(subset({4, 5, 6, 7}), every));

  models::fit_rule window;  // the protocol's rule: the finest five, attributable ones only
  window.finest = 5;
  BOOST_TEST(models::fitted_order(points, window) == models::fitted_order(subset({6, 8, 9, 10}), every));

  models::fit_rule plateau;  // nothing measurable among the finest three
  plateau.finest = 3;
  plateau.floor = 1e-9;
  BOOST_TEST(std::isnan(models::fitted_order(points, plateau)));
  models::fit_rule one;
  one.at_most = 1;
  BOOST_TEST(std::isnan(models::fitted_order(points, one)));
}

BOOST_AUTO_TEST_SUITE_END()  // free_body_observers_test
