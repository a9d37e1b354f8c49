// The free flight (T) of the torqued-body integrators with V = 0: SIER's is the exact free motion
// (translation q + t p/m, rotation by exact_free_rotation), checked against an independent float128
// solution of Euler's equations (RK4 + Richardson); SEJ4's rotor (a reconstruction) has the exact
// momentum and a 4th-order attitude, by fitted slope against the exact flow.
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <vector>

#include "md_support.hpp"
#include "model_support.hpp"
#include "rotlie/models/sej4_rotor.hpp"

BOOST_AUTO_TEST_SUITE(md_free_flight_test)

using namespace rotlie;
using models::vec3;
using rotlie::quad;

BOOST_AUTO_TEST_CASE(sier_free_flight_is_the_exact_motion) {
  const auto s0 = test::thermal_bodies<double>(3);
  const double h = 5.0;
  const long steps = 8;
  const vec3<quad> I = test::water_moments_real<quad>();
  for (const char* name : {"SIER2", "SIER4"}) {
    const auto s = test::run<double>(name, models::zero_potential<double>{}, s0, h, steps);
    for (std::size_t n = 0; n < s0.bodies.size(); ++n) {
      const auto& b0 = s0.bodies[n];
      models::body_state<quad> start;
      for (std::size_t i = 0; i < 9; ++i) start.Q.a[i] = b0.rot.Q.a[i];
      for (std::size_t i = 0; i < 3; ++i) start.G[i] = b0.rot.G[i];
      const auto ref = test::reference_solution(I, start, quad(h * steps), 4000);
      const double dQ = test::attitude_distance(s.bodies[n].rot.Q, ref.Q);
      double dG = 0;
      for (std::size_t i = 0; i < 3; ++i) dG = std::max(dG, std::abs(s.bodies[n].rot.G[i] - static_cast<double>(ref.G[i])) / 0.02);
      BOOST_TEST_MESSAGE(name << " body " << n << ": |Q − Q_ref| = " << dQ << ", |G − G_ref|/0.02 = " << dG);
      BOOST_TEST(dQ < 1e-13, name);  // ≈ 450 ε: the exact flow is exact to round-off
      BOOST_TEST(dG < 1e-13, name);
      for (std::size_t i = 0; i < 3; ++i) {
        const double q = b0.q[i] + h * steps * b0.p[i] / test::water_mass<double>();
        BOOST_TEST(std::abs(s.bodies[n].q[i] - q) < 1e-13, name);
        BOOST_TEST(s.bodies[n].p[i] == b0.p[i]);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(sej4_rotor_has_exact_momentum_and_a_fourth_order_attitude) {
  const auto I = test::water_moments_real<double>();
  const models::sej4_rotor<double> sej4(I);
  const models::exact_free_rotation<double> exact(I);
  const auto bodies = test::thermal_bodies<double>(3).bodies;
  const double T = 400;
  std::vector<double> hs, es;
  for (long n = 25; n <= 200; n *= 2) {
    const double h = T / static_cast<double>(n);
    double e = 0;
    for (const auto& b : bodies) {
      auto s = b.rot, r = b.rot;
      for (long k = 0; k < n; ++k) {
        sej4.advance(s, h);
        exact.advance(r, h);
        BOOST_TEST((s.G == r.G));  // the same exact momentum, step by step
      }
      e += test::attitude_distance(s.Q, r.Q);
    }
    hs.push_back(h);
    es.push_back(e);
  }
  const double p = test::fitted_slope(hs, es);
  BOOST_TEST_MESSAGE("SEJ4 rotor: attitude error slope " << p << ", e(16 fs) = " << es.front() << ", e(2 fs) = " << es.back());
  BOOST_TEST(std::abs(p - 4) < 0.15);
  BOOST_TEST(es.back() > 1e-10);
}

BOOST_AUTO_TEST_CASE(momenta_from_one_preparation_are_those_of_advance) {
  const auto I = test::water_moments_real<double>();
  const models::exact_free_rotation<double> exact(I);
  // thermal states, and a state on the largest axis (the steady regime, which the step declines)
  auto bodies = test::thermal_bodies<double>(4).bodies;
  bodies.push_back(bodies[0]);
  bodies.back().rot.G = {0, 0, 0.02};
  for (const auto& b : bodies)
    // SEJ4's Gauss nodes, backwards, and a time long enough (|v| > π/4) to be sent to exact_free_body
    for (const std::array<double, 3> t : {std::array<double, 3>{0.8, 3.2, 4.0}, std::array<double, 3>{-0.8, -3.2, -4.0},
                                          std::array<double, 3>{1.0, 2000.0, 3.0}}) {
      const auto G = exact.momenta(b.rot, t);
      for (std::size_t k = 0; k < 3; ++k) {
        auto s = b.rot;
        exact.advance(s, t[k]);
        BOOST_TEST((G[k] == s.G), "t = " << t[k]);
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()  // md_free_flight_test
