// NO_SQUISH (Miller et al. 2002: the free rotor split into rotations about the body axes, on a
// quaternion and its conjugate momentum) against the matrix planar rotations: conversions
// (Q, G) ↔ (q, π) round-trip, one sub-rotation matches rotate_about_axis, and the MD trajectory on
// the dipole in a strong field in DLM's axis order 1-2-3-2-1 (also LAMMPS's, in rotlie's
// increasing-moment numbering) is MRDL's (ABCBA2:ABC), in the reversed order 3-2-1-2-3
// MRDL-reversed's (ABCBA2:CBA), each to round-off growth, while the other order is not.
#include <boost/test/unit_test.hpp>

#include <cfloat>
#include <cmath>
#include <vector>

#include "md_support.hpp"
#include "model_support.hpp"
#include "rotlie/models/no_squish.hpp"
#include "rotlie/models/sub_flows.hpp"

BOOST_AUTO_TEST_SUITE(no_squish_test)

using namespace rotlie;
using models::vec3;

namespace {

double body_distance(const models::body_state<double>& a, const models::body_state<double>& b) {
  double g = 0;
  for (std::size_t i = 0; i < 3; ++i) g += (a.G[i] - b.G[i]) * (a.G[i] - b.G[i]);
  return test::attitude_distance(a.Q, b.Q) + std::sqrt(g) / 0.02;
}

// Strang-TV with the NO_SQUISH rotor, written directly on (q, π) as LAMMPS's fix rigid/nve does:
// half kick by the body torque, free rotation, half kick (the dipole exerts no force).
std::vector<models::body_state<double>> no_squish_md(const models::dipole_in_field<double>& scene, const models::axis_order& axes,
                                                     const std::vector<models::rigid_body_state<double>>& start, double h, long steps) {
  const models::no_squish_rotor<double> rotor(test::water_moments_real<double>(), axes);
  const double ftm2v = models::real_units::ftm2v<double>();
  std::vector<models::body_state<double>> out;
  for (const auto& b : start) {
    auto s = models::to_quaternion(b.rot);
    std::vector<models::rigid_body_state<double>> one(1);
    std::vector<vec3<double>> f(1), tau(1);
    auto half_kick = [&] {
      one[0].rot.Q = models::rotation_of(s.q);
      scene.evaluate(one, f, tau);
      const vec3<double> body_torque = models::transpose(one[0].rot.Q) * tau[0];
      models::no_squish_rotor<double>::kick(s, body_torque, h / 2 * ftm2v);
    };
    for (long k = 0; k < steps; ++k) {
      half_kick();
      rotor.advance(s, h);
      half_kick();
    }
    out.push_back(models::from_quaternion(s));
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(conversions_round_trip) {
  for (const auto& b : test::thermal_bodies<double>(4).bodies) {
    const auto q = models::to_quaternion(b.rot);
    BOOST_TEST(std::abs(q.q[0] * q.q[0] + q.q[1] * q.q[1] + q.q[2] * q.q[2] + q.q[3] * q.q[3] - 1) < 4e-16);
    BOOST_TEST(body_distance(models::from_quaternion(q), b.rot) < 4e-15);
  }
  // every branch of the matrix → quaternion conversion: rotations by ~π about each axis and the identity
  for (const vec3<double>& u : {vec3<double>{1, 0, 0}, vec3<double>{0, 1, 0}, vec3<double>{0, 0, 1}})
    for (const double angle : {0.0, 3.1, -3.1}) {
      const auto m = models::rotation(u, angle);
      BOOST_TEST(test::attitude_distance(models::rotation_of(models::quaternion_of(m)), m) < 4e-15);
    }
}

BOOST_AUTO_TEST_CASE(one_sub_rotation_is_the_planar_rotation) {
  const auto I = test::water_moments_real<double>();
  for (int k = 0; k < 3; ++k) {
    auto b = test::thermal_bodies<double>(2).bodies[1].rot;
    auto q = models::to_quaternion(b);
    models::no_squish_rotate(q, k, I[static_cast<std::size_t>(k)], 7.0);
    models::rotate_about_axis(b, k, 1 / I[static_cast<std::size_t>(k)], 7.0);
    BOOST_TEST(body_distance(models::from_quaternion(q), b) < 1e-14, "axis " << k);
  }
}

BOOST_AUTO_TEST_CASE(a_bad_axis_order_is_refused) {
  const auto I = test::water_moments_real<double>();
  for (const models::axis_order bad : {models::axis_order{0, 0, 1}, models::axis_order{0, 1, 3}, models::axis_order{-1, 1, 2}})
    BOOST_CHECK_THROW(models::no_squish_rotor<double>(I, bad), std::invalid_argument);
  BOOST_TEST((models::no_squish_rotor<double>(I).axes() == models::lammps_axis_order));
}

namespace {

// NO_SQUISH in `axes` against the named integrator with the same axis order and against the one
// with the other order.
void check_follows(const models::axis_order& axes, const char* same_order, const char* other_order) {
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  const auto s0 = test::thermal_bodies<double>(3);
  const double h = 4.0;
  for (const long steps : {1L, 100L, 1000L}) {
    const auto ns = no_squish_md(scene, axes, s0.bodies, h, steps);
    const auto matrix = test::run<double>(same_order, scene, s0, h, steps);
    const auto other = test::run<double>(other_order, scene, s0, h, steps);
    // the dynamics' own amplification of round-off: the matrix form from a start moved by 2 ε relative in G
    auto nudged = s0;
    for (auto& b : nudged.bodies)
      for (auto& g : b.rot.G) g *= 1 + 2 * DBL_EPSILON;
    const auto matrix_nudged = test::run<double>(same_order, scene, nudged, h, steps);
    double same = 0, different = 0, amplified = 0;
    for (std::size_t n = 0; n < ns.size(); ++n) {
      same += body_distance(ns[n], matrix.bodies[n].rot);
      different += body_distance(ns[n], other.bodies[n].rot);
      amplified += body_distance(matrix_nudged.bodies[n].rot, matrix.bodies[n].rot);
    }
    BOOST_TEST_MESSAGE(steps << " steps: NO_SQUISH vs " << same_order << " " << same << "; " << same_order
                             << " from a 2ε-nudged start " << amplified << "; NO_SQUISH vs " << other_order << " " << different);
    // round-off of a few ε per step, grown as the dynamics grows any 2ε difference (the strong field
    // makes the motion chaotic), against the O(h²) difference of the other axis order
    BOOST_TEST(same < 100 * amplified + 1e-13 * static_cast<double>(steps), same_order << ", " << steps << " steps");
    BOOST_TEST(different > 1e4 * same, same_order << ", " << steps << " steps");
  }
}

}  // namespace

// LAMMPS's order is DLM's in rotlie's numbering (liquid_water_lammps_test checks the map against LAMMPS)
BOOST_AUTO_TEST_CASE(no_squish_in_dlm_and_lammps_order_follows_mrdl_to_round_off) {
  check_follows(models::lammps_axis_order, "MRDL", "MRDL-reversed");
}

BOOST_AUTO_TEST_CASE(no_squish_in_reversed_order_follows_mrdl_reversed_to_round_off) {
  check_follows(models::reversed_axis_order, "MRDL-reversed", "MRDL");
}

BOOST_AUTO_TEST_SUITE_END()  // no_squish_test
