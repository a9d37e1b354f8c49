// The full two-body problem's integrators (binary_splitting, binary_anchors, binary_odeint) against
// independent expectations: the Kepler drift against Kepler's equation (kepler_orbit.hpp); at order 0
// the Kepler split is the exact orbit; each method's order by the slope of its error against a tight
// Runge–Kutta–Fehlberg 7(8) run; the splittings and the LGVI keep the total angular momentum to
// round-off; the synchronous planar equilibrium stays put.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "rotlie/models/closed_form_rotors.hpp"
#include "rotlie/models/composition.hpp"
#include "rotlie/models/scenes/binary_anchors.hpp"
#include "rotlie/models/scenes/binary_odeint.hpp"
#include "rotlie/models/scenes/binary_splitting.hpp"
#include "rotlie/models/scenes/kepler_orbit.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

BOOST_AUTO_TEST_SUITE(binary_integrators_test)

using namespace rotlie::models;

namespace {

double norm(const vec3<double>& v) { return std::sqrt(dot(v, v)); }

// Didymos-like proportions in units where G = 1: a flattened primary spinning fast, an elongated
// secondary near synchronous, tilted a little so that all three axes of both bodies move.
binary_system<double> didymos_like(int order) {
  return binary_system<double>(ellipsoid_body(5.2, 0.42, 0.40, 0.37), ellipsoid_body(0.048, 0.103, 0.079, 0.066), 1.0, order);
}

binary_state<double> didymos_like_start(const binary_system<double>& sys) {
  binary_state<double> x;
  const double R = 1.2, n = std::sqrt(sys.G() * sys.total_mass() / (R * R * R));
  x.r = {R, 0, 0};
  x.v = {0, 1.02 * n * R, 0.01 * n * R};
  x.body[0].Q = rotation<double>({0.0, 0.6, 0.8}, 0.1);
  x.body[0].G = {0.05 * sys.moments(0)[0], 0.02 * sys.moments(0)[1], 4.5 * n * sys.moments(0)[2]};
  x.body[1].Q = rotation<double>({0.6, 0.0, 0.8}, 0.05);
  x.body[1].G = {0.01 * sys.moments(1)[0], 0.0, 1.03 * n * sys.moments(1)[2]};
  return x;
}

double orbit_period(const binary_system<double>& sys) { return 2 * std::acos(-1.0) * std::sqrt(1.2 * 1.2 * 1.2 / (sys.G() * sys.total_mass())); }

// The distance between two states: position, velocity, both attitudes and angular momenta (scaled).
double state_distance(const binary_state<double>& a, const binary_state<double>& b) {
  double d = 0;
  for (std::size_t k = 0; k < 3; ++k) d = std::max({d, std::abs(a.r[k] - b.r[k]), std::abs(a.v[k] - b.v[k]) * 10});
  for (int i = 0; i < 2; ++i) {
    d = std::max(d, distance(a.body[i].Q, b.body[i].Q));
    const double g = norm(b.body[i].G);
    for (std::size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(a.body[i].G[k] - b.body[i].G[k]) / g);
  }
  return d;
}

template <class Visitor>
auto with_splitting(const char* tv, binary_drift drift, const binary_system<double>& sys, Visitor&& visit) {
  const exact_free_rotation<double> r1(sys.moments(0)), r2(sys.moments(1));
  const composition<binary_splitting<double, exact_free_rotation<double>>> method(*rotlie::schemes::reference_scheme(tv),
                                                                                  binary_splitting<double, exact_free_rotation<double>>(sys, r1, r2, drift));
  return visit(method);
}

binary_state<double> reference_end(const binary_system<double>& sys, const binary_state<double>& start, double T) {
  binary_odeint<double> ode(sys, odeint_method::rkf78, 1e-14, T / 1000);
  auto x = start;
  double t = 0;
  ode.advance(x, t, T);
  return x;
}

}  // namespace

// GM = 1, a = 1, pericentre on +x at t = 0: the drift lands where Kepler's equation puts the body.
BOOST_AUTO_TEST_CASE(the_kepler_drift_follows_keplers_equation) {
  for (const double e : {0.0, 0.1, 0.6, 0.95}) {
    const kepler_orbit<double> orbit(e);
    vec3<double> r{1 - e, 0, 0}, v{0, std::sqrt((1 + e) / (1 - e)), 0};
    double t = 0, worst = 0;
    for (int k = 0; k < 37; ++k) {
      const double dt = 0.37 + 0.01 * k;  // uneven steps, past several periods
      kepler_drift(r, v, 1.0, dt);
      t += dt;
      const auto p = orbit.at(t);
      worst = std::max({worst, std::abs(r[0] - p.r * p.cos_f), std::abs(r[1] - p.r * p.sin_f), std::abs(r[2])});
    }
    BOOST_TEST_MESSAGE("e = " << e << ": largest distance from Kepler's equation over " << t << " time units " << worst);
    BOOST_TEST(worst <= 1e-13 / (1 - e));
  }
  // a hyperbola, there and back: the drift is its own inverse with −dt
  vec3<double> r{1, 0, 0}, v{0, 1.8, 0.2};
  const auto r0 = r, v0 = v;
  kepler_drift(r, v, 1.0, 7.5);
  BOOST_TEST(2 / norm(r) - dot(v, v) == 2 / norm(r0) - dot(v0, v0), boost::test_tools::tolerance(1e-12));
  kepler_drift(r, v, 1.0, -7.5);
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(r[k] - r0[k]) + std::abs(v[k] - v0[k]) <= 1e-13);
}

// At order 0 the bodies are point masses: the Kepler split's kicks vanish and every step is the exact
// orbit (any step size), the rotations free.
BOOST_AUTO_TEST_CASE(at_order_zero_the_kepler_split_is_the_exact_orbit) {
  const auto sys = didymos_like(0);
  const auto start = didymos_like_start(sys);
  const double P = orbit_period(sys);
  with_splitting("PEFRL-TV", binary_drift::kepler, sys, [&](const auto& method) {
    binary_split_state<double> s{start};
    for (int k = 0; k < 7; ++k) method.step(s, P / 3.3);
    auto r = start.r, v = start.v;
    kepler_drift(r, v, sys.G() * sys.total_mass(), 7 * P / 3.3);
    for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(s.x.r[k] - r[k]) <= 1e-13);
    return 0;
  });
}

// Error after one mutual orbit against RKF78 at 1e-14, halving the step: the slopes of the splittings
// (2, 4 and 6, straight and Kepler drifts), RK4 (4) and the LGVI (2), at orders 2 and 4.
BOOST_AUTO_TEST_CASE(each_method_has_its_order) {
  for (const int order : {2, 4}) {
    const auto sys = didymos_like(order);
    const auto start = didymos_like_start(sys);
    const double P = orbit_period(sys);
    const auto reference = reference_end(sys, start, P);
    const auto slope_of = [&](const char* name, int expected, auto&& run) {
      double errors[2];
      for (int j = 0; j < 2; ++j) {
        const long steps = (expected == 2 ? 400L : std::string(name) == "RK4" ? 800L : expected == 6 ? 50L : 100L) << j;
        errors[j] = state_distance(run(P / static_cast<double>(steps), steps), reference);
      }
      const double slope = std::log2(errors[0] / errors[1]);
      BOOST_TEST_MESSAGE("order " << order << ", " << name << ": error " << errors[1] << ", slope " << slope);
      BOOST_TEST(std::abs(slope - expected) < 0.2, name << " at order " << order << ": slope " << slope);
    };
    for (const auto& [name, tv, drift, expected] : {std::tuple{"SIER2", "Strang-TV", binary_drift::straight, 2}, std::tuple{"SIER4", "PEFRL-TV", binary_drift::straight, 4},
                                                    std::tuple{"KEPLER2", "Strang-TV", binary_drift::kepler, 2}, std::tuple{"KEPLER4", "PEFRL-TV", binary_drift::kepler, 4},
                                                    std::tuple{"SIER6", "KahanLi6-TV", binary_drift::straight, 6}, std::tuple{"KEPLER6", "KahanLi6-TV", binary_drift::kepler, 6}})
      slope_of(name, expected, [&, tv = tv, drift = drift](double h, long steps) {
        return with_splitting(tv, drift, sys, [&](const auto& method) {
          binary_split_state<double> s{start};
          for (long k = 0; k < steps; ++k) method.step(s, h);
          return s.x;
        });
      });
    slope_of("RK4", 4, [&](double h, long steps) {
      const binary_rk4<double> rk4(sys);
      auto x = start;
      for (long k = 0; k < steps; ++k) rk4.step(x, h);
      return x;
    });
    slope_of("LGVI", 2, [&](double h, long steps) {
      const binary_lgvi<double> lgvi(sys);
      auto x = start;
      mutual_gravity<double> g;
      bool valid = false;
      for (long k = 0; k < steps; ++k) lgvi.step(x, h, g, valid);
      return x;
    });
  }
}

// The splittings and the LGVI keep r × μv + Q₁G₁ + Q₂G₂ to round-off (each flow does, binary_splitting.hpp;
// the LGVI by its discrete Noether theorem); the energy error stays bounded.
BOOST_AUTO_TEST_CASE(splittings_and_the_lgvi_keep_the_total_angular_momentum) {
  const auto sys = didymos_like(4);
  const auto start = didymos_like_start(sys);
  const double P = orbit_period(sys), h = P / 200;
  const long steps = 200 * 20;
  const auto L0 = sys.angular_momentum(start);
  const double E0 = sys.energy(start);
  const auto check = [&](const char* name, auto&& step) {
    auto x = start;
    double worst_L = 0, worst_E = 0;
    for (long k = 0; k < steps; ++k) {
      step(x);
      const auto L = sys.angular_momentum(x);
      for (std::size_t i = 0; i < 3; ++i) worst_L = std::max(worst_L, std::abs(L[i] - L0[i]) / norm(L0));
      if (k % 50 == 0) worst_E = std::max(worst_E, std::abs(sys.energy(x) - E0) / std::abs(E0));
    }
    BOOST_TEST_MESSAGE(name << ", 20 orbits of 200 steps: largest relative change of L " << worst_L << ", of E " << worst_E);
    BOOST_TEST(worst_L <= 64 * std::numeric_limits<double>::epsilon() * std::sqrt(double(steps)), name);
    BOOST_TEST(worst_E <= 1e-4, name);
  };
  for (const auto& [name, tv, drift] : {std::tuple{"SIER2", "Strang-TV", binary_drift::straight}, std::tuple{"SIER4", "PEFRL-TV", binary_drift::straight},
                                        std::tuple{"KEPLER2", "Strang-TV", binary_drift::kepler}, std::tuple{"KEPLER4", "PEFRL-TV", binary_drift::kepler}})
    with_splitting(tv, drift, sys, [&, name = name](const auto& method) {
      binary_split_state<double> s{start};
      check(name, [&](binary_state<double>& x) {
        s.x = x;
        method.step(s, h);
        x = s.x;
      });
      return 0;
    });
  const binary_lgvi<double> lgvi(sys);
  mutual_gravity<double> g;
  bool valid = false;
  check("LGVI", [&](binary_state<double>& x) { lgvi.step(x, h, g, valid); });
}

// An oblate primary (a = b) spinning about its axis and a secondary whose long axis points at it, on
// the circular orbit whose rate balances the mutual force at that configuration (not Kepler's: the
// bodies' second- and fourth-degree terms pull too): a relative equilibrium. Over 10 orbits the
// separation and the secondary's alignment stay put to 1e-9; started at Kepler's rate instead, the
// same pair swings by more than 1e-4 (the test tells the equilibrium apart).
BOOST_AUTO_TEST_CASE(the_synchronous_planar_equilibrium_stays_put) {
  const binary_system<double> sys(ellipsoid_body(5.2, 0.42, 0.42, 0.37), ellipsoid_body(0.048, 0.103, 0.079, 0.066), 1.0, 4);
  const double R = 1.2;
  const auto swing = [&](double n) {
    binary_state<double> x;
    x.r = {R, 0, 0};
    x.v = {0, n * R, 0};
    x.body[0].G = {0, 0, 3 * n * sys.moments(0)[2]};
    x.body[1].G = {0, 0, n * sys.moments(1)[2]};
    return with_splitting("PEFRL-TV", binary_drift::kepler, sys, [&](const auto& method) {
      binary_split_state<double> s{x};
      const double P = 2 * std::acos(-1.0) / n;
      double worst = 0;
      for (int k = 0; k < 10 * 200; ++k) {
        method.step(s, P / 200);
        // the separation, and the sine of the angle between the secondary's long axis (body x) and r̂
        const vec3<double> axis{s.x.body[1].Q(0, 0), s.x.body[1].Q(1, 0), s.x.body[1].Q(2, 0)};
        worst = std::max({worst, std::abs(norm(s.x.r) - R) / R, norm(cross(axis, s.x.r)) / norm(s.x.r)});
      }
      return worst;
    });
  };
  binary_state<double> at_rest;
  at_rest.r = {R, 0, 0};
  const double balanced = std::sqrt(-sys.gravity(at_rest).F[0] / (sys.reduced_mass() * R)), kepler = std::sqrt(sys.total_mass() / (R * R * R));
  const double kept = swing(balanced), swung = swing(kepler);
  BOOST_TEST_MESSAGE("10 orbits of 200 KEPLER4 steps: the equilibrium kept to " << kept << "; at Kepler's rate (" << kepler / balanced
                                                                                 << " of the balanced one) the pair swings by " << swung);
  BOOST_TEST(kept <= 1e-9);
  BOOST_TEST(swung >= 1e-4);
}

BOOST_AUTO_TEST_SUITE_END()  // binary_integrators_test
