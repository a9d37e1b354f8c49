// The exact sub-flows: φ_s ∘ φ_t = φ_{s+t}; the attitude stays orthogonal with det 1 to round-off;
// |G| and the energy of the flowing part are conserved; the RS gathering of the rotations about G
// gives the same step as applying them stage by stage.
#include <boost/test/unit_test.hpp>

#include <random>

#include "model_support.hpp"
#include "random_seed.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

BOOST_AUTO_TEST_SUITE(sub_flows_test)

using namespace rotlie;
using models::body_state;
using models::vec3;

namespace {

body_state<double> random_state(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  body_state<double> s;
  s.G = {n(rng), n(rng), n(rng)};
  const vec3<double> axis0{n(rng), n(rng), n(rng)};
  const double l = std::sqrt(models::dot(axis0, axis0));
  s.Q = models::rotation(vec3<double>{axis0[0] / l, axis0[1] / l, axis0[2] / l}, n(rng));
  return s;
}

double orthogonality_defect(const models::mat3<double>& Q) {
  const auto P = models::transpose(Q) * Q;
  return models::distance(P, models::mat3<double>::identity());
}

double det(const models::mat3<double>& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

}  // namespace

BOOST_AUTO_TEST_CASE(axis_flows_compose_and_conserve) {
  std::mt19937_64 rng(test::test_seed("axis_flows_compose_and_conserve"));
  std::uniform_real_distribution<double> t(-2, 2);
  for (int trial = 0; trial < 200; ++trial) {
    const auto s0 = random_state(rng);
    const int k = trial % 3;
    const double rate = 0.5 + trial * 0.01, a = t(rng), b = t(rng);
    auto s1 = s0, s2 = s0;
    models::rotate_about_axis(s1, k, rate, a);
    models::rotate_about_axis(s1, k, rate, b);
    models::rotate_about_axis(s2, k, rate, a + b);
    BOOST_TEST(models::distance(s1.Q, s2.Q) < 1e-13);
    BOOST_TEST(std::abs(s1.G[static_cast<std::size_t>(k)] - s0.G[static_cast<std::size_t>(k)]) == 0.0);  // G_k fixed
    BOOST_TEST(std::abs(models::dot(s1.G, s1.G) - models::dot(s0.G, s0.G)) < 1e-13 * models::dot(s0.G, s0.G));
    BOOST_TEST(orthogonality_defect(s1.Q) < 1e-14);
    BOOST_TEST(std::abs(det(s1.Q) - 1) < 1e-14);
    // the inertial angular momentum Q·G is conserved by every sub-flow
    const auto m0 = s0.Q * s0.G, m1 = s1.Q * s1.G;
    BOOST_TEST(std::abs(m0[0] - m1[0]) + std::abs(m0[1] - m1[1]) + std::abs(m0[2] - m1[2]) < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(momentum_flow_composes_and_fixes_g) {
  std::mt19937_64 rng(test::test_seed("momentum_flow_composes_and_fixes_g"));
  for (int trial = 0; trial < 100; ++trial) {
    const auto s0 = random_state(rng);
    auto s1 = s0, s2 = s0;
    models::rotate_about_momentum(s1, 1.3, 0.4);
    models::rotate_about_momentum(s1, 1.3, -1.1);
    models::rotate_about_momentum(s2, 1.3, -0.7);
    BOOST_TEST(models::distance(s1.Q, s2.Q) < 1e-13);
    BOOST_TEST(s1.G == s0.G);
    const auto m0 = s0.Q * s0.G, m1 = s1.Q * s1.G;
    BOOST_TEST(std::abs(m0[0] - m1[0]) + std::abs(m0[1] - m1[1]) + std::abs(m0[2] - m1[2]) < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(each_part_conserves_its_energy_and_the_scheme_keeps_the_casimir) {
  const auto I = test::water_moments<double>();
  const auto table = *schemes::reference_scheme("ABCBA4-SS3-Yoshida");
  models::composition_stepper<double> stepper(table, I);
  auto s = test::initial_state<double>({1, 1, 1});
  const double g2 = models::dot(s.G, s.G);
  for (int n = 0; n < 10000; ++n) stepper.step(s, 0.05);
  BOOST_TEST(std::abs(models::dot(s.G, s.G) - g2) < 1e-11);
  BOOST_TEST(orthogonality_defect(s.Q) < 1e-12);
  // energy: symplectic, so bounded oscillation of size O(h^4), no drift
  BOOST_TEST(std::abs(models::kinetic_energy(I, s.G) - models::kinetic_energy(I, test::initial_state<double>({1, 1, 1}).G)) < 1e-5);
}

BOOST_AUTO_TEST_CASE(rs_gathering_equals_stage_by_stage) {
  // S = G3²/2 (1/I3 − 1/I2) + G²/(2 I2): doing the G² rotation inside every S stage, or once per step,
  // gives the same step because it commutes with everything (section 3.1.2).
  const auto I = test::water_moments<double>();
  const auto table = *schemes::reference_scheme("RSR4-SS3-Yoshida");
  models::composition_stepper<double> stepper(table, I);
  auto gathered = test::initial_state<double>({0.3, -1.2, 0.8});
  auto staged = gathered;
  const double h = 0.1;
  stepper.step(gathered, h);
  for (const auto& st : table.stages) {
    const double c = std::stod(st.value);
    if (st.part == 'R') {
      models::rotate_about_axis(staged, 0, 1 / I[0] - 1 / I[1], c * h);
    } else {
      models::rotate_about_axis(staged, 2, 1 / I[2] - 1 / I[1], c * h);
      models::rotate_about_momentum(staged, 1 / I[1], c * h);
    }
  }
  BOOST_TEST(models::distance(gathered.Q, staged.Q) < 1e-14);
}

BOOST_AUTO_TEST_CASE(stepper_refuses_bad_tables_and_bodies) {
  auto table = *schemes::reference_scheme("ABCBA2");
  table.stages[2].value = "0.5";
  BOOST_CHECK_THROW(models::composition_stepper<double>(table, test::water_moments<double>()), std::invalid_argument);
  const auto good = *schemes::reference_scheme("ABCBA2");
  BOOST_CHECK_THROW(models::composition_stepper<double>(good, vec3<double>{1, 1, 3}), std::invalid_argument);
  BOOST_CHECK_THROW(models::composition_stepper<double>(good, vec3<double>{std::nan(""), 1, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // sub_flows_test
