// The exact flow in double on a grid of hard regimes, against an independent float128 solution of
// Euler's equations (RK4 + Richardson, model_support.hpp): near-spherical bodies (prolate, oblate,
// triaxial; anisotropy 1e-3 … 1e-12), the unstable middle axis (offsets 1e-2 … 1e-15 and exactly on
// the separatrix, every sign of G1, G3), near the separatrix away from the middle axis (δ = 1e-3 …
// 1e-15 and 2e-22, against an energy-projected reference), thin and flat bodies, |G| from 1e-150
// to 1e150 (through the scaling law G → sG, t → t/s, which the reference does not use), long times up to the stated
// limit and the refusal beyond it, the flow property, and the error estimate (never below the
// measured error). Target: max abs entry of Q and of G/|G| within 1e-12. Errors are printed.
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/cpp_int.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <stdexcept>

#include "free_body_samples.hpp"
#include "model_support.hpp"
#include "random_seed.hpp"
#include "rotlie/models/exact_free_body.hpp"

BOOST_AUTO_TEST_SUITE(exact_flow_regimes_test)

using namespace rotlie;
using models::vec3;
using rotlie::quad;

namespace {

constexpr double target = 1e-12;
constexpr double reference_floor = 1e-15;  // RK4 + Richardson at 400 steps per radian

template <class T>
vec3<T> to(const vec3<double>& v) {
  return {T(v[0]), T(v[1]), T(v[2])};
}

using test::entry_error;  // max abs entry of Q and of G/|G|

std::string sci(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

double norm(const vec3<double>& g) { return std::hypot(g[0], g[1], g[2]); }

models::body_state<quad> rk_reference(const vec3<double>& I, const vec3<double>& G, double t) {
  const double omega = norm(G) / std::min({I[0], I[1], I[2]});
  const long steps = static_cast<long>(400 * omega * t) + 10;
  return test::reference_solution(to<quad>(I), test::initial_state<quad>(to<quad>(G)), quad(t), steps);
}

// The double exact flow at t against the RK reference: asserts the target and the estimate.
double check(const std::string& label, const vec3<double>& I, const vec3<double>& G, double t) {
  const models::exact_free_body<double> flow(I, test::initial_state<double>(G));
  const auto r = flow.evaluate(t);
  const double e = entry_error(r.state, rk_reference(I, G, t), norm(G));
  BOOST_TEST_MESSAGE(label << ": error " << e << ", estimate " << r.error_estimate << ", m_c " << flow.complementary_parameter());
  BOOST_TEST(e < target, label << ": " << e);
  BOOST_TEST(e <= r.error_estimate + reference_floor, label << ": error " << e << " above its estimate " << r.error_estimate);
  return e;
}

const vec3<double> water{10220.0 / 29376, 19187.0 / 29376, 1};

// RK4 + Richardson as above, with G projected after every step back onto the two invariants |G|²
// and 2E = Σ G_i²/I_i, both taken in float128 from the double inputs (G_i² exact there). Near the
// separatrix the phase of the motion depends on D_y = |G|² − 2E I_y relative to its own size δ|G|²;
// plain RK4 drifts in E by far more than δ = 1e-15, the projected one by ~1e-32 |G|².
models::body_state<quad> projected_rk4(const vec3<quad>& I, models::body_state<quad> s, const quad& t, long steps) {
  auto invariants = [&I](const vec3<quad>& g) {
    return std::pair{g[0] * g[0] + g[1] * g[1] + g[2] * g[2], g[0] * g[0] / I[0] + g[1] * g[1] / I[1] + g[2] * g[2] / I[2]};
  };
  const auto [c1, c2] = invariants(s.G);
  const quad h = t / steps;
  for (long n = 0; n < steps; ++n) {
    s = models::integrate_rk4(I, s, h, 1);
    for (int it = 0; it < 2; ++it) {  // Newton on G + a G + b G/I: the residual is O(h⁵), then O(h¹⁰)
      const auto [r1, r2] = invariants(s.G);
      quad j11 = 0, j12 = 0, j22 = 0;  // Jacobian of (|G|², 2E) in (a, b), halved
      for (std::size_t i = 0; i < 3; ++i) {
        const quad g2 = s.G[i] * s.G[i];
        j11 += g2, j12 += g2 / I[i], j22 += g2 / (I[i] * I[i]);
      }
      const quad f1 = (c1 - r1) / 2, f2 = (c2 - r2) / 2, det = j11 * j22 - j12 * j12;
      const quad a = (f1 * j22 - f2 * j12) / det, b = (j11 * f2 - j12 * f1) / det;
      for (std::size_t i = 0; i < 3; ++i) s.G[i] += a * s.G[i] + b * s.G[i] / I[i];
    }
  }
  return s;
}

models::body_state<quad> projected_reference(const vec3<double>& I, const vec3<double>& G, double t) {
  const long steps = static_cast<long>(400 * norm(G) / std::min({I[0], I[1], I[2]}) * t) + 10;
  const auto s0 = test::initial_state<quad>(to<quad>(G));
  const auto coarse = projected_rk4(to<quad>(I), s0, quad(t), steps), fine = projected_rk4(to<quad>(I), s0, quad(t), 2 * steps);
  models::body_state<quad> r;
  for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = (16 * fine.Q.a[i] - coarse.Q.a[i]) / 15;
  for (std::size_t i = 0; i < 3; ++i) r.G[i] = (16 * fine.G[i] - coarse.G[i]) / 15;
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(near_spherical_bodies) {
  for (const double a : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const std::string s = " anisotropy " + sci(a);
    check("prolate" + s, {1, 1, 1 + a}, {0.3, 1, 0.7}, 3);
    check("oblate" + s, {1, 1 + a, 1 + a}, {0.3, 1, 0.7}, 3);
    check("triaxial" + s, {1, 1 + a, 1 + 2 * a}, {0.3, 1, 0.7}, 3);
    check("triaxial, I2 near I3," + s, {1, 1 + a, 1 + 1.0000001 * a}, {0.3, 0.7, 1}, 3);
    check("triaxial, I2 near I1," + s, {1, 1 + 1e-7 * a, 1 + a}, {1, 0.7, 0.3}, 3);
  }
}

BOOST_AUTO_TEST_CASE(middle_axis_offsets) {
  // G(0) = (±d, 1, ±d) for water: m_c ≈ 2d², down to below the double resolution of m
  for (const double d : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-15})
    for (const double s1 : {1.0, -1.0})
      for (const double s3 : {1.0, -1.0})
        check("middle axis d = " + sci(d) + " signs " + sci(s1) + "," + sci(s3), water,
              {s1 * d, 1, s3 * d}, 7);
}

BOOST_AUTO_TEST_CASE(exactly_on_the_separatrix) {
  // I = (3, 15/4, 5), G = (±1, g, ±1): D_y = G1²(I1 − I2)/I1 + G3²(I3 − I2)/I3 = −1/4 + 1/4 = 0 exactly
  const vec3<double> I{3, 3.75, 5};
  for (const double g : {0.5, 0.0, -2.0})
    for (const double s1 : {1.0, -1.0})
      for (const double s3 : {1.0, -1.0}) {
        const models::exact_free_body<double> flow(I, test::initial_state<double>({s1, g, s3}));
        BOOST_TEST(flow.complementary_parameter() == 0.0);
        // D_y = 0 is exact here (products of order 1): the double closed form answers, its estimate is
        // its own, not the "unrepresentable" mark of a state whose products underflowed
        BOOST_TEST(flow.evaluate(10).error_estimate < 1e-13);
        check("separatrix g = " + sci(g) + " signs " + sci(s1) + "," + sci(s3), I,
              {s1, g, s3}, 10);
      }
}

BOOST_AUTO_TEST_CASE(thin_and_flat_bodies) {
  check("flat I1 + I2 = I3", {0.25, 0.75, 1}, {0.3, 1, 0.7}, 3);
  check("flat symmetric", {0.5, 0.5, 1}, {0.3, 1, 0.7}, 3);
  check("flat, near-symmetric 1e-9", {0.5, 0.5 + 1e-9, 1}, {0.3, 1, 0.7}, 3);
  check("flat, near-symmetric, near axis 1", {0.5, 0.5 + 1e-9, 1}, {1, 1e-3, 1e-3}, 3);
  check("flat on the middle axis", {0.5, 0.5, 1}, {0, 1, 1e-9}, 3);
  // thin: the spin about the thin axis is 1e8 times faster; the reference resolves t = 1e-6
  check("thin rod 1e-8", {1e-8, 1, 1}, {0.3, 1, 0.7}, 1e-6);
  check("thin rod 1e-8, I3 + 1e-8", {1e-8, 1, 1 + 1e-8}, {0.3, 1, 0.7}, 1e-6);
  check("thin rod 1e-8, I2 − 1e-8", {1e-8, 1 - 1e-8, 1}, {0.3, 1, 0.7}, 1e-6);
}

BOOST_AUTO_TEST_CASE(near_the_separatrix_away_from_the_middle_axis) {
  // I = (1, 2, 3), G = (1, 1, √3 (1 + δ)) as doubles: D_y = G3²/3 − 1 ≈ 2δ is what is left of terms
  // of size 1 (summed in double it would carry an error of ~1e-16, i.e. relative 1e-16/δ, and the
  // phase with it). Also a state at δ ≈ 2e-22 whose doubles are a convergent of √3 (G2 = 0).
  const vec3<double> I{1, 2, 3};
  std::vector<std::pair<std::string, vec3<double>>> cases;
  for (int k = 3; k <= 15; ++k) {
    const double delta = std::pow(10.0, -k);
    cases.push_back({"delta = " + sci(delta), {1, 1, std::sqrt(3.0) * (1 + delta)}});
  }
  cases.push_back({"delta = 2e-22", {0.5180697268109302, 0, 0.8973230886998593}});
  for (const auto& [label, G] : cases) {
    const double t = 40;
    const models::exact_free_body<double> flow(I, test::initial_state<double>(G));
    const auto r = flow.evaluate(t);
    const double e = entry_error(r.state, projected_reference(I, G, t), norm(G));
    BOOST_TEST_MESSAGE(label << ": error " << e << ", estimate " << r.error_estimate << ", m_c " << flow.complementary_parameter());
    BOOST_TEST(flow.complementary_parameter() > 0.0, label);
    BOOST_TEST(e < target, label << ": " << e);
    BOOST_TEST(e <= r.error_estimate + reference_floor, label << ": error " << e << " above its estimate " << r.error_estimate);
  }
}

BOOST_AUTO_TEST_CASE(middle_energy_difference_is_correct_to_its_last_places) {
  // D_y = G1²(I1 − I2)/I1 + G3²(I3 − I2)/I3 against exact rational arithmetic, on both of its paths
  // (double-double, and the exact sum when the terms cancel to below 64ε of themselves)
  using rational = boost::multiprecision::cpp_rational;
  auto exact = [](const auto& I, const auto& G) {
    auto r = [](const auto& v) { return rational(v); };
    return r(G[0]) * r(G[0]) * (r(I[0]) - r(I[1])) / r(I[0]) + r(G[2]) * r(G[2]) * (r(I[2]) - r(I[1])) / r(I[2]);
  };
  auto check_relative = [&](const auto& I, const auto& G, double eps, const std::string& label) {
    using S = std::decay_t<decltype(I[0])>;
    bool inexact = true;
    const S d = models::detail::middle_energy_difference<S>(I, G, 0, 1, 2, inexact);
    BOOST_TEST(!inexact, label);
    const rational e = exact(I, G);
    BOOST_TEST_REQUIRE(e != 0, label);
    const rational rel = abs((rational(d) - e) / e);
    BOOST_TEST(static_cast<double>(rel) <= 4 * eps, label << ": relative error " << static_cast<double>(rel));
  };
  const vec3<double> I{1, 2, 3}, water_I = water;
  for (int k = 0; k <= 16; ++k) {
    const double delta = std::pow(10.0, -k);
    check_relative(I, vec3<double>{1, 1, std::sqrt(3.0) * (1 + delta)}, 0x1p-53, "double, delta " + sci(delta));
    check_relative(water_I, vec3<double>{0.3 + delta, 0.5, 1.59048173339384 * 0.3}, 0x1p-53, "water, delta " + sci(delta));
  }
  check_relative(I, vec3<double>{0.5180697268109302, 0, 0.8973230886998593}, 0x1p-53, "double, delta 2e-22");
  check_relative(I, vec3<double>{0.6627976094924595, 0, 1.1479991347761358}, 0x1p-53, "double, delta 4e-32");
  // float128 inputs that are not doubles
  const vec3<quad> Iq{1, 2, 3};
  for (const int k : {5, 20, 30, 33})
    check_relative(Iq, vec3<quad>{1, 1, sqrt(quad(3)) * (1 + pow(quad(10), -k))}, 0x1p-113, "float128, delta 1e-" + std::to_string(k));
}

BOOST_AUTO_TEST_CASE(flat_body_one_ulp_outside_the_triangle_inequality) {
  // 0.3 + 0.6 < 0.9 in double by one ulp: meant as the flat body I3 = I1 + I2, accepted as such
  const vec3<double> I{0.3, 0.6, 0.9};
  BOOST_TEST(I[0] + I[1] < I[2]);
  check("flat by rounding 0.3, 0.6, 0.9", I, {0.3, 1, 0.7}, 3);
  BOOST_CHECK_THROW(models::exact_free_body<double>({0.3, 0.6, 0.9 * (1 + 1e-14)}, test::initial_state<double>({1, 1, 1})),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(float128_flow_agrees_with_the_independent_reference_where_it_is_used_below) {
  // The long-time and fast-spin checks below use the float128 exact flow as reference: shown here
  // to agree with RK4 + Richardson on the same bodies over times the integrator can reach.
  for (const auto& [I, G, t] : {std::tuple{water, vec3<double>{1, 1, 1}, 40.0}, std::tuple{vec3<double>{1e-8, 1, 1}, vec3<double>{0.3, 1, 0.7}, 2e-6},
                                std::tuple{water, vec3<double>{1e-12, 1, 1e-12}, 20.0}}) {
    const models::exact_free_body<quad> exact(to<quad>(I), test::initial_state<quad>(to<quad>(G)));
    const double e = entry_error(exact.at(quad(t)), rk_reference(I, G, t), norm(G));
    BOOST_TEST_MESSAGE("float128 exact flow against RK4 + Richardson, t = " << t << ": " << e);
    BOOST_TEST(e < 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(momentum_scale_from_1e_minus_150_to_1e150) {
  // The motion with G scaled by s is the motion at time s·t: reference = RK at |G| = O(1).
  const vec3<double> I{0.4, 0.7, 1}, G{0.1, 1, 0.2};
  const double t = 3;
  const auto reference = rk_reference(I, G, t);
  for (const double s : {1e-150, 1e-20, 1.0, 1e20, 1e150}) {
    const models::exact_free_body<double> flow(I, test::initial_state<double>({s * G[0], s * G[1], s * G[2]}));
    const auto r = flow.evaluate(t / s);
    models::body_state<quad> scaled = reference;
    for (auto& g : scaled.G) g *= s;
    const double e = entry_error(r.state, scaled, s * norm(G));
    BOOST_TEST_MESSAGE("|G| scaled by " << s << ": error " << e << ", estimate " << r.error_estimate);
    BOOST_TEST(e < target);
    BOOST_TEST(e <= r.error_estimate + reference_floor);
  }
  // the moments in any unit: I scaled by c is the motion at time t/c
  for (const double c : {1e-100, 1e100}) {
    const models::exact_free_body<double> flow({c * I[0], c * I[1], c * I[2]}, test::initial_state<double>(G));
    const double e = entry_error(flow.at(c * t), reference, norm(G));
    BOOST_TEST_MESSAGE("I scaled by " << c << ": error " << e);
    BOOST_TEST(e < target);
  }
}

BOOST_AUTO_TEST_CASE(long_times_and_the_refusal_beyond_the_limit) {
  // reference: the float128 exact flow (checked against RK above); the double flow redoes in
  // float128 once its estimate passes 1e-12, so the target holds up to the limit
  for (const auto& [I, G] : {std::pair{water, vec3<double>{1, 1, 1}}, std::pair{water, vec3<double>{1e-12, 1, 1e-12}},
                             std::pair{vec3<double>{1e-8, 1, 1}, vec3<double>{0.3, 1, 0.7}}}) {
    const models::exact_free_body<double> flow(I, test::initial_state<double>(G));
    const models::exact_free_body<quad> exact(to<quad>(I), test::initial_state<quad>(to<quad>(G)));
    for (const double fraction : {1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.999}) {
      const double t = fraction * flow.max_time();
      const auto r = flow.evaluate(t);
      const auto q = exact.evaluate(quad(t));
      const double e = entry_error(r.state, q.state, norm(G));
      BOOST_TEST_MESSAGE("t = " << t << " (" << fraction << " of the limit): error " << e << ", estimate " << r.error_estimate
                                << ", float128 estimate " << q.error_estimate);
      BOOST_TEST(e <= r.error_estimate + static_cast<double>(q.error_estimate));
      if (q.error_estimate < 1e-14) BOOST_TEST(e < target);
    }
    BOOST_CHECK_THROW(flow.at(flow.max_time() * 1.001), std::domain_error);
    BOOST_CHECK_THROW(flow.at(-flow.max_time() * 1.001), std::domain_error);
    BOOST_CHECK_THROW(flow.at(std::numeric_limits<double>::infinity()), std::domain_error);
    BOOST_CHECK_THROW(flow.at(std::nan("")), std::domain_error);
  }
}

BOOST_AUTO_TEST_CASE(flow_property_across_regimes) {
  // φ_s ∘ φ_t = φ_{s+t}: restart from the state at t (attitude included) and go on for s
  const std::vector<std::pair<vec3<double>, vec3<double>>> cases{
      {water, {1, 1, 1}},       {water, {1e-10, 1, -1e-10}},     {{3, 3.75, 5}, {-1, 0.5, 1}},
      {{1, 1 + 1e-12, 1 + 2e-12}, {0.3, 1, 0.7}}, {{0.25, 0.75, 1}, {0.3, 1, 0.7}}, {{1e-8, 1, 1}, {0.3, 1, 0.7}}};
  for (const auto& [I, G] : cases) {
    const models::exact_free_body<double> a(I, test::initial_state<double>(G));
    for (const auto& [t, s] : {std::pair{0.7, 2.3}, std::pair{5.1, -1.9}}) {
      const double scale = 1 / (norm(G) / std::min({I[0], I[1], I[2]}));  // times in units of 1/|ω|
      const models::exact_free_body<double> b(I, a.at(t * scale));
      const double e = entry_error(b.at(s * scale), a.at((t + s) * scale), norm(G));
      BOOST_TEST_MESSAGE("flow property, G = (" << G[0] << ", " << G[1] << ", " << G[2] << "): " << e);
      BOOST_TEST(e < target);
    }
  }
}

BOOST_AUTO_TEST_CASE(wobble_below_the_underflow_threshold) {
  // G within 1e-300 of a principal axis, at |G| = 1e300 or 1: the wobble's amplitude underflows in
  // the scaled units; the answer is the steady rotation about ω, exact to that amplitude.
  for (const auto& G : {vec3<double>{1e300, 1, 1}, vec3<double>{1, 1e-300, 1e-300}, vec3<double>{1e-300, 1e-300, 1},
                        vec3<double>{1e-170, 1e-170, 1}}) {
    const double s = norm(G);
    const vec3<double> unit{G[0] / s, G[1] / s, G[2] / s};
    const auto reference = rk_reference(water, unit, 3);  // the same motion at |G| = 1, time 3
    const models::exact_free_body<double> flow(water, test::initial_state<double>(G));
    auto scaled = reference;
    for (auto& g : scaled.G) g *= s;
    const auto r = flow.evaluate(3 / s);
    const double e = entry_error(r.state, scaled, s);
    BOOST_TEST_MESSAGE("G = (" << G[0] << ", " << G[1] << ", " << G[2] << "): error " << e << ", estimate " << r.error_estimate);
    BOOST_TEST(e < target);
  }
}

BOOST_AUTO_TEST_CASE(random_states_in_every_regime_stay_within_their_estimate) {
  // Random bodies (generic, near-spherical, thin, flat near-symmetric), momenta whose components
  // span 1e-300 … 1 of each other at |G| from 1e-100 to 1e100, times up to the limit: the double
  // flow agrees with its float128 instance within the double's own estimate, and the estimate
  // stays below the target wherever the float128 instance is sure of itself. No NaN, no exception.
  std::mt19937_64 rng(test::test_seed("exact_flow random_states"));
  std::uniform_real_distribution<double> U(0, 1);
  int checked = 0;
  double worst = 0;
  for (int it = 0; it < 3000; ++it) {
    const double a = std::pow(10.0, -16 * U(rng));
    vec3<double> I;
    switch (it % 4) {
      case 0: I = {0.2 + 0.8 * U(rng), 0.2 + 0.8 * U(rng), 0.2 + 0.8 * U(rng)}; break;
      case 1: I = {1, 1 + a * U(rng), 1 + a}; break;
      case 2: I = {std::pow(10.0, -10 * U(rng)), 1, 1 + a * (U(rng) - 0.5)}; break;
      default: I = {0.5, 0.5 + a, 1};
    }
    if (I[2] > I[0] + I[1] || I[0] > I[1] + I[2] || I[1] > I[0] + I[2]) continue;
    vec3<double> G;
    const double scale = std::pow(10.0, 200 * (U(rng) - 0.5));
    for (auto& g : G) g = (U(rng) < 0.5 ? -1 : 1) * std::pow(10.0, U(rng) < 0.3 ? -300 * U(rng) : -3 * U(rng)) * scale;
    const models::exact_free_body<double> flow(I, test::initial_state<double>(G));
    const models::exact_free_body<quad> exact(to<quad>(I), test::initial_state<quad>(to<quad>(G)));
    const double limit = std::min(static_cast<double>(flow.max_time()), 1e300);  // infinite for subnormal |G|
    const double t = limit * std::pow(10.0, -18 * U(rng) - 2) * (U(rng) < 0.5 ? -1 : 1);
    const auto r = flow.evaluate(t);
    const auto q = exact.evaluate(quad(t));
    // every component may underflow to 0 (10^-300 · 10^-100): G/|G| has no direction, compare G as it is
    const double e = entry_error(r.state, q.state, norm(G) > 0 ? norm(G) : 1.0);
    const double ratio = e / (r.error_estimate + static_cast<double>(q.error_estimate));
    worst = std::max(worst, ratio);
    ++checked;
    BOOST_TEST(ratio <= 1, "I = (" << I[0] << ", " << I[1] << ", " << I[2] << "), G = (" << G[0] << ", " << G[1] << ", " << G[2]
                                   << "), t = " << t << ": error " << e << ", estimate " << r.error_estimate);
    if (q.error_estimate < 1e-20) BOOST_TEST(e < target);
  }
  BOOST_TEST_MESSAGE(checked << " random states: largest error / estimate " << worst);
}

BOOST_AUTO_TEST_CASE(a_body_at_rest_stays_at_rest) {
  // G = 0: no rotation at any time, no time limit (|ω| = 0), and no division by the zero rate
  const vec3<double> I{1, 2, 2.5};
  auto start = test::initial_state<double>(vec3<double>{0, 0, 0});
  start.Q.a = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  const models::exact_free_body<double> flow(I, start);
  BOOST_TEST(std::isinf(flow.max_time()));
  const auto r = flow.evaluate(1e6);
  BOOST_TEST(r.error_estimate <= 8 * std::numeric_limits<double>::epsilon());  // the floor of every estimate
  for (std::size_t i = 0; i < 9; ++i) BOOST_TEST(r.state.Q.a[i] == start.Q.a[i]);
  for (std::size_t i = 0; i < 3; ++i) BOOST_TEST(r.state.G[i] == 0.0);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused) {
  BOOST_CHECK_THROW(models::exact_free_body<double>(water, test::initial_state<double>({std::nan(""), 1, 1})), std::invalid_argument);
  BOOST_CHECK_THROW(models::exact_free_body<double>(water, test::initial_state<double>({1e308 * 10, 1, 1})), std::invalid_argument);
  BOOST_CHECK_THROW(models::exact_free_body<double>({1, 1, 3}, test::initial_state<double>({1, 1, 1})), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(every_scalar_meets_the_target_in_the_hard_regimes) {
  // the class is templated on the scalar: long double and float128 against the same RK reference
  const std::vector<std::pair<vec3<double>, vec3<double>>> cases{
      {water, {1e-12, 1, 1e-12}}, {{3, 3.75, 5}, {-1, 0.5, 1}}, {{1, 1 + 1e-12, 1 + 2e-12}, {0.3, 1, 0.7}}, {{0.25, 0.75, 1}, {0.3, 1, 0.7}}};
  for (const auto& [I, G] : cases) {
    const auto reference = rk_reference(I, G, 3);
    const models::exact_free_body<long double> ld(to<long double>(I), test::initial_state<long double>(to<long double>(G)));
    const models::exact_free_body<quad> q(to<quad>(I), test::initial_state<quad>(to<quad>(G)));
    const double e_ld = entry_error(ld.at(3.0L), reference, norm(G)), e_q = entry_error(q.at(quad(3)), reference, norm(G));
    BOOST_TEST_MESSAGE("long double " << e_ld << ", float128 " << e_q << " (reference floor " << reference_floor << ")");
    BOOST_TEST(e_ld < 1e-15);
    BOOST_TEST(e_q < reference_floor);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // exact_flow_regimes_test
