// The exact free rotation of many bodies at once (advance_block, advance_all) against the step of
// one body (exact_free_rotation::advance): random bodies of every kind the regime test covers, and
// blocks that mix the common regime with every hard one (the separatrix, steady rotations, a wobble
// below the underflow threshold, m_c < 1/4, extreme |G|, long times and the float128 redo, large
// phases): each body's result must be advance's within the two evaluations' error estimates (round-
// off), the estimates alike. Carlson's R_J written for the vector code against Boost's.
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "free_body_samples.hpp"
#include "random_seed.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"

BOOST_AUTO_TEST_SUITE(exact_free_rotation_batch_test)

using namespace rotlie;
using models::body_state;
using models::vec3;

namespace {

const vec3<double> water_I = test::water_moments<double>();

struct lane {
  body_state<double> s;
  double t;
  std::string label;
};

// Every lane advanced by the block and one by one; each difference within the two estimates (and
// the estimates within a factor 2 of each other). Returns how many lanes the vector code took.
std::size_t check_block(const vec3<double>& I, const std::vector<lane>& lanes, const std::string& what) {
  const models::exact_free_rotation<double> rotor(I);
  models::free_body_block block;
  block.n = lanes.size();
  for (std::size_t i = 0; i < block.n; ++i) {
    const auto& x = lanes[i];
    for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = x.s.G[k];
    for (std::size_t e = 0; e < 9; ++e) block.Q[e][i] = x.s.Q.a[e];
    block.t[i] = x.t;
  }
  std::size_t vectorised = 0, one_by_one = 0;
  models::advance_block(rotor, block, &vectorised, &one_by_one);
  BOOST_TEST(vectorised + one_by_one == block.n, what);
  for (std::size_t i = 0; i < block.n; ++i) {
    body_state<double> single = lanes[i].s, batch;
    const double e_single = rotor.advance(single, lanes[i].t);
    for (std::size_t k = 0; k < 3; ++k) batch.G[k] = block.G[k][i];
    for (std::size_t e = 0; e < 9; ++e) batch.Q.a[e] = block.Q[e][i];
    const double e_batch = block.estimate[i];
    const double difference = test::entry_error(batch, single, test::norm(single.G));
    BOOST_TEST(difference <= 2 * (e_single + e_batch), what << ", " << lanes[i].label << " (lane " << i << "): " << difference
                                                            << " against the estimates " << e_single << ", " << e_batch);
    BOOST_TEST((e_batch <= 2 * e_single && e_single <= 2 * e_batch), what << ", " << lanes[i].label << ": estimates " << e_single << ", " << e_batch);
  }
  return vectorised;
}

}  // namespace

BOOST_AUTO_TEST_CASE(carlson_rj_is_boosts) {
  std::mt19937_64 rng(test::test_seed("carlson_rj_is_boosts"));
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const double x = k % 7 == 0 ? 0.0 : 2 * U(rng), y = 2 * U(rng) + 1e-3, z = 2 * U(rng) + 1e-3, p = std::pow(10.0, 3 * U(rng) - 2);
    const double ours = models::elliptic::carlson_rj(x, y, z, p), boost = boost::math::ellint_rj(x, y, z, p);
    worst = std::max(worst, std::abs(ours / boost - 1));
  }
  BOOST_TEST_MESSAGE("largest relative difference from Boost's R_J over 20,000 arguments: " << worst);
  BOOST_TEST(worst <= 16 * std::numeric_limits<double>::epsilon());
  // long double, at the arguments of a step
  const long double ours = models::elliptic::carlson_rj(0.81L, 0.9L, 1.0L, 1.05L), boost = boost::math::ellint_rj(0.81L, 0.9L, 1.0L, 1.05L);
  BOOST_TEST(std::abs(ours / boost - 1) <= 16 * std::numeric_limits<long double>::epsilon());
}

BOOST_AUTO_TEST_CASE(the_batch_is_the_step_on_random_bodies) {
  test::sampler draw("the_batch_is_the_step_on_random_bodies");
  std::size_t vectorised = 0, total = 0;
  for (int kind = 0; kind < 6; ++kind)
    for (int body = 0; body < 12; ++body) {
      const auto first = draw.next(kind);
      std::vector<lane> lanes;
      for (std::size_t i = 0; i < models::free_body_block::capacity; ++i) {
        // the state of a new draw with the first body's moments, its time rescaled to keep |ω| t
        const auto x = i == 0 ? first : draw.next(kind);
        lanes.push_back({x.s, x.t * std::min({first.I[0], first.I[1], first.I[2]}) / std::min({x.I[0], x.I[1], x.I[2]}), first.kind});
      }
      vectorised += check_block(first.I, lanes, first.kind + " body " + std::to_string(body));
      total += lanes.size();
    }
  BOOST_TEST_MESSAGE("vector target " << models::batch_target() << ": " << vectorised << " of " << total << " lanes vectorised");
  if (models::batch_target() != "none") BOOST_TEST(vectorised > total / 4);
}

BOOST_AUTO_TEST_CASE(a_block_mixing_regimes_is_the_step_lane_by_lane) {
  std::mt19937_64 rng(test::test_seed("a_block_mixing_regimes_is_the_step_lane_by_lane"));
  std::normal_distribution<double> N(0, 1);
  const auto Q0 = models::rotation<double>({0.6, 0, 0.8}, 0.7);
  const auto state = [&](vec3<double> G) {
    body_state<double> s;
    s.G = G, s.Q = Q0;
    return s;
  };
  std::vector<lane> lanes = {
      {state({1, 1, 1}), 0.05, "common"},
      {state({0, 1.3, 0}), 0.1, "steady about the middle axis"},
      {state({0, 0, 1.3}), 0.1, "steady about the largest axis"},
      {state({1e-9, 1, 1e-9}), 0.1, "near the middle axis (m_c < 1/4)"},
      {state({1e-300, 1e-300, 1}), 0.1, "wobble below the underflow threshold"},
      {state({1, 1, 1}), 1e6, "long time: the float128 redo"},
      {state({1, 1, 1}), 3.0, "large phase step"},
      {state({1e200, 1e200, 1e200}), 1e-200, "|G| = 1e200"},
      {state({1e-200, -1e-200, 1e-200}), 1e199, "|G| = 1e-200"},
      {state({1, 1, 1}), 0.0, "t = 0"},
      {state({1, 1, 1}), -0.05, "t < 0"},
  };
  for (int k = 0; k < 21; ++k) lanes.push_back({state({N(rng), N(rng), N(rng)}), 0.2 * N(rng), "random"});
  const std::size_t mixed = check_block(water_I, lanes, "water, mixed");
  if (models::batch_target() != "none") {
    BOOST_TEST(mixed > 0u);
    BOOST_TEST(mixed < lanes.size());
  }
  // the separatrix of (3, 3.75, 5) beside common states of that body
  std::vector<lane> separatrix = {{state({1, 0.5, -1}), 0.1, "on the separatrix"}};
  for (int k = 0; k < 7; ++k) separatrix.push_back({state({N(rng), N(rng), N(rng)}), 0.1 * N(rng), "random"});
  check_block({3, 3.75, 5}, separatrix, "separatrix");
  // a spherical body takes the general path for every lane
  check_block({1, 1, 1}, {{state({0.3, 1, 0.7}), 0.1, "spherical"}, {state({1, 2, 3}), 0.2, "spherical"}}, "sphere");
}

BOOST_AUTO_TEST_CASE(advance_all_pads_and_returns_every_body) {
  std::mt19937_64 rng(test::test_seed("advance_all_pads_and_returns_every_body"));
  std::normal_distribution<double> N(0, 1);
  const models::exact_free_rotation<double> rotor(water_I);
  for (const std::size_t n : {1u, 5u, 64u, 100u}) {
    std::vector<body_state<double>> bodies(n);
    for (auto& b : bodies) b.G = {N(rng), N(rng), N(rng)}, b.Q = models::rotation<double>({0, 0.6, 0.8}, N(rng));
    auto single = bodies;
    std::vector<double> estimates(n, -1);
    models::advance_all(
        rotor, n, [&](std::size_t i) -> body_state<double>& { return bodies[i]; }, 0.08, [&](std::size_t i, double e) { estimates[i] = e; });
    for (std::size_t i = 0; i < n; ++i) {
      const double e = rotor.advance(single[i], 0.08);
      BOOST_TEST(test::entry_error(bodies[i], single[i], test::norm(single[i].G)) <= 2 * (e + estimates[i]), "n = " << n << ", body " << i);
      BOOST_TEST(estimates[i] > 0, "n = " << n << ", body " << i);
    }
  }
}

// Bodies of one shape whose moments differ (LAMMPS computes each molecule's from its atoms), each with
// its own rotor; among them bodies of other shapes (their own axis order: the scalar step) and
// hard states. Each lane against its own rotor's step within the estimates.
BOOST_AUTO_TEST_CASE(each_lane_its_own_rotor) {
  std::mt19937_64 rng(test::test_seed("each_lane_its_own_rotor"));
  std::normal_distribution<double> N(0, 1);
  std::uniform_real_distribution<double> spread(-1, 1);
  const std::size_t n = 61;  // a last vector with padding
  std::vector<models::exact_free_rotation<double>> rotors;
  std::vector<vec3<double>> moments;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < n; ++i) {
    vec3<double> I = water_I;
    std::string label = "water, moments within 1e-13";
    if (i % 10 == 3) I = {5, 3.75, 3}, label = "a body with its axes in another order";
    else if (i % 10 == 7) label = "water, moments within 1e-7";
    const double size = i % 10 == 7 ? 1e-7 : 1e-13;
    for (auto& m : I) m *= 1 + size * spread(rng);
    moments.push_back(I), labels.push_back(label);
  }
  rotors.reserve(n);
  for (const auto& I : moments) rotors.emplace_back(I);
  std::vector<const models::exact_free_rotation<double>*> pointers;
  for (const auto& r : rotors) pointers.push_back(&r);
  models::free_body_block block;
  block.n = n;
  std::vector<body_state<double>> start(n);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    start[i].G = {N(rng), N(rng), N(rng)};
    if (i == 11) start[i].G = {1e-9, 1, 1e-9}, labels[i] += ", near the middle axis";
    if (i == 21) start[i].G = {0, 0, 1.3}, labels[i] += ", steady";
    start[i].Q = models::rotation<double>({0, 0.6, 0.8}, N(rng));
    t[i] = i == 31 ? 1e6 : 0.1 * N(rng);
    if (i == 31) labels[i] += ", the float128 redo";
    for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = start[i].G[k];
    for (std::size_t e = 0; e < 9; ++e) block.Q[e][i] = start[i].Q.a[e];
    block.t[i] = t[i];
  }
  std::size_t vectorised = 0, one_by_one = 0;
  models::advance_block(pointers.data(), block, &vectorised, &one_by_one);
  BOOST_TEST(vectorised + one_by_one == n);
  for (std::size_t i = 0; i < n; ++i) {
    body_state<double> single = start[i], batch;
    const double e_single = rotors[i].advance(single, t[i]);
    for (std::size_t k = 0; k < 3; ++k) batch.G[k] = block.G[k][i];
    for (std::size_t e = 0; e < 9; ++e) batch.Q.a[e] = block.Q[e][i];
    const double e_batch = block.estimate[i];
    const double difference = test::entry_error(batch, single, test::norm(single.G));
    BOOST_TEST(difference <= 2 * (e_single + e_batch), labels[i] << " (lane " << i << "): " << difference << " against " << e_single << ", " << e_batch);
    BOOST_TEST((e_batch <= 2 * e_single && e_single <= 2 * e_batch), labels[i] << ": estimates " << e_single << ", " << e_batch);
  }
  BOOST_TEST_MESSAGE("own rotors: " << vectorised << " of " << n << " lanes vectorised");
  if (models::batch_target() != "none") BOOST_TEST(vectorised >= n / 2);
  // the other shapes' lanes cannot share lane 0's vector step
  if (models::batch_target() != "none") BOOST_TEST(one_by_one >= 6u);
}

// A body's result is the same alone and among others, at any lane (each lane computes alone; the
// block pads its last vector itself), bit for bit.
BOOST_AUTO_TEST_CASE(a_body_alone_is_the_body_in_a_block) {
  std::mt19937_64 rng(test::test_seed("a_body_alone_is_the_body_in_a_block"));
  std::normal_distribution<double> N(0, 1);
  const models::exact_free_rotation<double> rotor(water_I);
  body_state<double> body;
  body.G = {0.3, -1.1, 0.7};
  body.Q = models::rotation<double>({0, 0.6, 0.8}, 0.4);
  const auto load = [](models::free_body_block& block, std::size_t i, const body_state<double>& s, double t) {
    for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = s.G[k];
    for (std::size_t e = 0; e < 9; ++e) block.Q[e][i] = s.Q.a[e];
    block.t[i] = t;
  };
  models::free_body_block alone;
  alone.n = 1;
  load(alone, 0, body, 0.08);
  models::advance_block(rotor, alone);
  for (const std::size_t n : {5u, 13u, 64u}) {
    models::free_body_block block;
    block.n = n;
    const std::size_t at = n - 1;
    for (std::size_t i = 0; i < n; ++i) {
      body_state<double> other;
      other.G = {N(rng), N(rng), N(rng)};
      other.Q = models::rotation<double>({0.6, 0, 0.8}, N(rng));
      load(block, i, i == at ? body : other, i == at ? 0.08 : 0.1 * N(rng));
    }
    models::advance_block(rotor, block);
    for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(block.G[k][at] == alone.G[k][0], "n = " << n);
    for (std::size_t e = 0; e < 9; ++e) BOOST_TEST(block.Q[e][at] == alone.Q[e][0], "n = " << n);
    BOOST_TEST(block.estimate[at] == alone.estimate[0], "n = " << n);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // exact_free_rotation_batch_test
