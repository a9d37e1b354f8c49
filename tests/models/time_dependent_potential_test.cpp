// A potential that depends on time, against its closed form: a body driven by a uniform force
// F(t) = E cos ωt and a lab torque τ(t) = τ₀ cos ωt ẑ, spinning about its largest principal axis
// along z (a steady rotation that the torque speeds up and slows down, never tilts). In natural units
// (unit_system::natural(): every factor 1) the exact motion is
//   p(t) = p₀ + E sin(ωt)/ω,                 q(t) = q₀ + p₀ t/m + E (1 − cos ωt)/(m ω²),
//   L_z(t) = L₀ + τ₀ sin(ωt)/ω,              Q(t) = R_z(φ),  φ = (L₀ t + τ₀ (1 − cos ωt)/ω²)/I₃.
// Each kick must read the force at its own stage's time: SIER2 (Strang-TV) then converges at order 2
// and SIER4 (PEFRL-TV) at order 4; kicks that all read the step's start time would give order 1.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(time_dependent_potential_test)

using namespace rotlie::models;

namespace {

constexpr double omega = 2, tau0 = 0.7, L0 = 1.1, mass = 2, T_end = 3;
const vec3<double> E{1, 0.5, -0.25}, p0{0.3, -0.1, 0.2}, I{1, 2, 3};

/// V(q, Q, t) = −cos(ωt) (E·q + τ₀ φ), φ the rotation angle about z (the only rotation here).
struct pulsed_drive {
  bool acts() const { return true; }
  double evaluate(const std::vector<rigid_body_state<double>>& bodies, std::vector<vec3<double>>& force,
                  std::vector<vec3<double>>& torque, const double& t) const {
    const double c = std::cos(omega * t);
    double V = 0;
    for (std::size_t n = 0; n < bodies.size(); ++n) {
      const auto& b = bodies[n];
      const double phi = std::atan2(b.rot.Q(1, 0), b.rot.Q(0, 0));
      V -= c * (dot(E, b.q) + tau0 * phi);
      force[n] = {c * E[0], c * E[1], c * E[2]};
      torque[n] = {0, 0, c * tau0};
    }
    return V;
  }
};

rigid_bodies_state<double> start() {
  rigid_bodies_state<double> s;
  rigid_body_state<double> b;
  b.p = p0;
  b.rot.G = {0, 0, L0};  // along body axis 3 = lab z (Q = 1)
  s.bodies.push_back(b);
  return s;
}

/// The largest distance of the computed state from the closed form at T_end (p, q, L_z and Q).
double error_at_end(const std::string& integrator, long steps) {
  const double h = T_end / static_cast<double>(steps);
  return with_md_integrator<double>(rotlie::test::splitting(integrator), std::vector<body_kind<double>>{{mass, I}}, pulsed_drive{},
                                    unit_system<double>::natural(), [&](const auto& method) {
                                      auto x = start();
                                      for (long k = 0; k < steps; ++k) method.step(x, h);
                                      const double t = x.t, s = std::sin(omega * t), c = std::cos(omega * t);
                                      const auto& b = x.bodies[0];
                                      double e = std::abs(t - T_end);
                                      for (std::size_t i = 0; i < 3; ++i) {
                                        e = std::max(e, std::abs(b.p[i] - (p0[i] + E[i] * s / omega)));
                                        e = std::max(e, std::abs(b.q[i] - (p0[i] * t / mass + E[i] * (1 - c) / (mass * omega * omega))));
                                      }
                                      const double Lz = L0 + tau0 * s / omega, phi = (L0 * t + tau0 * (1 - c) / (omega * omega)) / I[2];
                                      e = std::max(e, std::abs(b.rot.G[2] - Lz));
                                      const auto Q = rotation(vec3<double>{0, 0, 1}, phi);
                                      for (std::size_t i = 0; i < 9; ++i) e = std::max(e, std::abs(b.rot.Q.a[i] - Q.a[i]));
                                      return e;
                                    });
}

double observed_order(const std::string& integrator, long steps) {
  return std::log2(error_at_end(integrator, steps) / error_at_end(integrator, 2 * steps));
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_kicks_read_the_force_at_their_stage_time) {
  // the clock: T_end reached to round-off, and a stage time in between seen by the second kick
  BOOST_TEST(error_at_end("SIER2", 64) < 1e-3);
  BOOST_TEST(error_at_end("SIER2", 1024) < 4e-6);
}

BOOST_AUTO_TEST_CASE(sier2_converges_at_order_two_on_a_time_dependent_drive) {
  const double p = observed_order("SIER2", 128);
  BOOST_TEST_MESSAGE("SIER2 order " << p);
  BOOST_TEST(p > 1.95);
  BOOST_TEST(p < 2.05);
}

BOOST_AUTO_TEST_CASE(sier4_converges_at_order_four_on_a_time_dependent_drive) {
  const double p = observed_order("SIER4", 32);
  BOOST_TEST_MESSAGE("SIER4 order " << p);
  BOOST_TEST(p > 3.9);
  BOOST_TEST(p < 4.1);
}

BOOST_AUTO_TEST_CASE(a_table_rotor_converges_at_order_two_as_well) {
  const double p = observed_order("MRDL", 128);  // the rotation about one axis is exact for any rotor
  BOOST_TEST(p > 1.95);
  BOOST_TEST(p < 2.05);
}

BOOST_AUTO_TEST_SUITE_END()  // time_dependent_potential_test
