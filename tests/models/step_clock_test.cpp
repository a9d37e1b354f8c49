// The engine's clock for a time-dependent potential (step_clock.hpp): the time after step k is fl(k h)
// exactly, however many steps, and every kick reads (k + C_j) h to about an ulp, C_j the sum of the
// table's free-flight coefficients before the kick, computed here independently in long double. A
// clock summed stage by stage (t += c h) drifts by thousands of ulps over the 10⁶ steps below.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(step_clock_test)

using namespace rotlie::models;

namespace {

/// V = t·(1 + q_x), no torque, a force that does not depend on time, so the clock is all that this
/// records: the time of each evaluation.
struct recording_potential {
  std::vector<double>* seen;
  bool acts() const { return true; }
  double evaluate(const std::vector<rigid_body_state<double>>& bodies, std::vector<vec3<double>>& force, std::vector<vec3<double>>& torque,
                  const double& t) const {
    seen->push_back(t);
    force[0] = {-1e-3, 0, 0};
    torque[0] = {};
    return t * (1 + bodies[0].q[0]);
  }
};

rigid_bodies_state<double> one_body() {
  rigid_bodies_state<double> x;
  rigid_body_state<double> b;
  b.p = {0.1, 0, 0};
  b.rot.G = {0.01, 0.02, 0.3};
  x.bodies.push_back(b);
  return x;
}

/// The kick times of one step as fractions of h, from PEFRL-TV's coefficients read in long double.
std::vector<long double> kick_fractions() {
  const auto table = *rotlie::schemes::reference_scheme("PEFRL-TV");
  std::vector<long double> out;
  long double c = 0;
  for (const auto& s : table.stages) {
    if (s.part == 'T')
      c += std::strtold(s.value.c_str(), nullptr);
    else
      out.push_back(c);
  }
  return out;
}

/// The distance of t from the nearest (k + C_j) h, in ulps of t.
double ulps_from_grid(double t, long double h, const std::vector<long double>& fractions) {
  const long double k = std::floor(static_cast<long double>(t) / h);
  long double best = std::numeric_limits<long double>::infinity();
  for (long double dk : {-1.0L, 0.0L, 1.0L})
    for (long double c : fractions) best = std::min(best, std::fabs(static_cast<long double>(t) - (k + dk + c) * h));
  const double ulp = std::nextafter(std::fabs(t), std::numeric_limits<double>::infinity()) - std::fabs(t);
  return static_cast<double>(best / ulp);
}

template <class F>
void with_sier4(std::vector<double>& seen, F&& f) {
  with_md_integrator<double>(rotlie::test::splitting("SIER4"), std::vector<body_kind<double>>{{1.0, {1, 2, 3}}}, recording_potential{&seen},
                             unit_system<double>::natural(), [&](const auto& method) {
                               f(method);
                               return 0;
                             });
}

}  // namespace

BOOST_AUTO_TEST_CASE(after_a_million_steps_the_clock_reads_k_h_exactly_and_every_kick_its_stage_time) {
  const double h = 2 * std::numbers::pi / 1000;  // the spin-orbit scene's 1/1000 orbit
  const long steps = 1000000;
  std::vector<double> seen;
  seen.reserve(4 * steps + 8);
  long off_grid = 0;
  double t_end = 0;
  with_sier4(seen, [&](const auto& method) {
    auto x = one_body();
    for (long k = 1; k <= steps; ++k) {
      method.step(x, h);
      off_grid += x.t != static_cast<double>(k) * h;
    }
    t_end = x.t;
  });
  BOOST_TEST(off_grid == 0);
  BOOST_TEST(t_end == static_cast<double>(steps) * h);
  const auto fractions = kick_fractions();
  double worst = 0;
  for (double t : seen) worst = std::max(worst, ulps_from_grid(t, h, fractions));
  BOOST_TEST_MESSAGE("kicks: " << seen.size() << ", worst distance from (k + C_j) h: " << worst << " ulp");
  BOOST_TEST(seen.size() >= static_cast<std::size_t>(4 * steps));  // first-same-as-last: 4 evaluations a step of 5 kicks
  BOOST_TEST(worst <= 2.0);
}

BOOST_AUTO_TEST_CASE(a_clock_set_by_hand_or_a_new_step_starts_a_new_count) {
  std::vector<double> seen;
  with_sier4(seen, [&](const auto& method) {
    auto x = one_body();
    const double h = 0.1;
    for (int k = 0; k < 7; ++k) method.step(x, h);
    BOOST_TEST(x.t == 7 * h);
    x.t = 5;  // set from outside: counted from 5 on
    for (int k = 1; k <= 1000; ++k) {
      method.step(x, h);
      BOOST_TEST_REQUIRE(x.t == 5 + static_cast<double>(k) * h);
    }
    const double t0 = x.t, h2 = 0.03;  // a new step: counted from where the old count ended
    for (int k = 1; k <= 1000; ++k) method.step(x, h2);
    BOOST_TEST(x.t == t0 + 1000 * h2);
    const double t1 = x.t;  // and back: the adjoint step returns the clock to where it was
    for (int k = 1; k <= 1000; ++k) method.step(x, -h2);
    BOOST_TEST(x.t == t1 + 1000 * -h2);
  });
}

BOOST_AUTO_TEST_CASE(a_free_flight_called_alone_still_advances_the_clock) {
  std::vector<double> seen;
  with_sier4(seen, [&](const auto& method) {
    auto x = one_body();
    method.system().free_flight(0.25, x);
    BOOST_TEST(x.t == 0.25);
  });
}

BOOST_AUTO_TEST_SUITE_END()  // step_clock_test
