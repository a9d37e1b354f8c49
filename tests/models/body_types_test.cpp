// Several body types in one system: each body's type gives its mass, moments and rotor.
//  - Without interaction (a dipole of each body in a uniform field), a system of water molecules
//    and asymmetric tops side by side gives every body the very bits it gets in a system of its own
//    type alone, for the exact rotor (SIER4) and a table rotor (MRDL).
//  - With interaction (springs between body-fixed sites of different types, which exchange forces
//    and torques), the energy is conserved at the order of the integrator: its largest error over
//    the run falls by 2² (SIER2) and 2⁴ (SIER4) when the step is halved.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/dipole_in_field.hpp"
#include "rotlie/models/scenes/water.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(body_types_test)

using namespace rotlie::models;

namespace {

using state = rigid_bodies_state<double>;

// water (real units) and a heavier asymmetric top, I₁ < I₂ < I₃ with I₃ < I₁ + I₂
const body_kind<double> water_kind{water::mass<double>(), water::moments<double>()};
const body_kind<double> top_kind{30.0, {1.3, 2.1, 2.9}};

/// Bodies of thermal size (real units) at spread positions and tilted attitudes, of the given types.
state bodies_of_types(const std::vector<unsigned>& types) {
  state s;
  for (std::size_t k = 0; k < types.size(); ++k) {
    rigid_body_state<double> b;
    const double d = static_cast<double>(k);
    b.type = types[k];
    b.q = {3 * d, -d, 0.5 * d};
    b.p = {0.05 - 0.01 * d, 0.02 * d, 0.01};
    b.rot.G = {0.011 + 0.003 * d, -0.019 + 0.002 * d, 0.013 - 0.004 * d};
    b.rot.Q = rotation(vec3<double>{1.0 / 3, 2.0 / 3, 2.0 / 3}, 0.4 + 0.7 * d);
    s.bodies.push_back(b);
  }
  return s;
}

/// `steps` steps of `integrator` with step h on bodies of the kinds listed, under `potential`.
template <class Potential>
state run(const std::string& integrator, const std::vector<body_kind<double>>& kinds, const Potential& potential,
          const unit_system<double>& units, state x, double h, long steps) {
  return with_md_integrator<double>(rotlie::test::splitting(integrator), kinds, potential, units, [&](const auto& method) {
    for (long k = 0; k < steps; ++k) method.step(x, h);
    return x;
  });
}

/// The bodies of one type out of a mixed state, renumbered as type 0 (a system of that type alone).
state only_type(const state& mixed, unsigned type) {
  state s;
  for (auto b : mixed.bodies)
    if (b.type == type) {
      b.type = 0;
      s.bodies.push_back(b);
    }
  return s;
}

bool same_bits(const rigid_body_state<double>& a, const rigid_body_state<double>& b) {
  for (std::size_t i = 0; i < 3; ++i)
    if (a.q[i] != b.q[i] || a.p[i] != b.p[i] || a.rot.G[i] != b.rot.G[i]) return false;
  for (std::size_t i = 0; i < 9; ++i)
    if (a.rot.Q.a[i] != b.rot.Q.a[i]) return false;
  return true;
}

/// Springs of stiffness k between body-fixed sites, V = k/2 Σ_{i<j} |s_i − s_j|², s_i = q_i + Q_i a_type(i):
/// forces on the centres and torques (Q_i a) × F_i that couple the types' rotations.
struct site_springs {
  double k = 1;
  std::vector<vec3<double>> site;  ///< per body type, in its body frame
  bool acts() const { return true; }
  double evaluate(const std::vector<rigid_body_state<double>>& bodies, std::vector<vec3<double>>& force,
                  std::vector<vec3<double>>& torque) const {
    std::vector<vec3<double>> arm(bodies.size()), s(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      arm[i] = bodies[i].rot.Q * site[bodies[i].type];
      for (std::size_t d = 0; d < 3; ++d) s[i][d] = bodies[i].q[d] + arm[i][d];
      force[i] = {};
    }
    double V = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = i + 1; j < bodies.size(); ++j) {
        const vec3<double> r{s[i][0] - s[j][0], s[i][1] - s[j][1], s[i][2] - s[j][2]};
        V += k / 2 * dot(r, r);
        for (std::size_t d = 0; d < 3; ++d) {
          force[i][d] -= k * r[d];
          force[j][d] += k * r[d];
        }
      }
    for (std::size_t i = 0; i < bodies.size(); ++i) torque[i] = cross(arm[i], force[i]);
    return V;
  }
};

/// Largest |E − E₀| over `steps` steps of size h (natural units: two types coupled by springs).
double energy_error(const std::string& integrator, double h, long steps) {
  const std::vector<body_kind<double>> kinds{{1.0, {1, 2, 2.5}}, {2.0, {0.5, 0.8, 1.1}}};
  const site_springs springs{1.0, {{0.3, 0.1, -0.2}, {-0.1, 0.4, 0.2}}};
  state x = bodies_of_types({0, 1, 1, 0});
  for (auto& b : x.bodies)
    for (auto& g : b.rot.G) g *= 40;  // rotations as fast as the springs' oscillations
  return with_md_integrator<double>(rotlie::test::splitting(integrator), kinds, springs, unit_system<double>::natural(),
                                    [&](const auto& method) {
                                      const auto& sys = method.system();
                                      const double E0 = sys.energy(x);
                                      double worst = 0;
                                      for (long k = 0; k < steps; ++k) {
                                        method.step(x, h);
                                        worst = std::max(worst, std::abs(sys.energy(x) - E0));
                                      }
                                      return worst;
                                    });
}

}  // namespace

BOOST_AUTO_TEST_CASE(independent_bodies_of_two_types_move_as_in_their_own_systems) {
  const dipole_in_field<double> field(0.4, 1, {0, 0, 0.5});  // each body's own torque, no interaction
  const auto units = unit_system<double>::real();
  const state mixed = bodies_of_types({0, 1, 0, 1, 1});
  for (const std::string integrator : {"SIER4", "MRDL", "SEJ4"}) {
    const state together = run(integrator, {water_kind, top_kind}, field, units, mixed, 4.0, 200);
    const state waters = run(integrator, {water_kind}, field, units, only_type(mixed, 0), 4.0, 200);
    const state tops = run(integrator, {top_kind}, field, units, only_type(mixed, 1), 4.0, 200);
    std::size_t w = 0, t = 0;
    for (const auto& b : together.bodies) {
      auto alone = b.type == 0 ? waters.bodies[w++] : tops.bodies[t++];
      alone.type = b.type;
      BOOST_TEST(same_bits(b, alone), integrator << ": a body of type " << b.type << " moved differently beside the other type");
    }
    BOOST_TEST(together.t == waters.t);
  }
}

BOOST_AUTO_TEST_CASE(two_types_under_one_type_each_differ) {
  // the types matter: the same bodies all of one type end elsewhere
  const dipole_in_field<double> field(0.4, 1, {0, 0, 0.5});
  const auto units = unit_system<double>::real();
  const state mixed = bodies_of_types({0, 1});
  const state together = run("SIER2", {water_kind, top_kind}, field, units, mixed, 4.0, 50);
  state all_water = mixed;
  all_water.bodies[1].type = 0;
  const state one_type = run("SIER2", {water_kind, top_kind}, field, units, all_water, 4.0, 50);
  BOOST_TEST(same_bits(together.bodies[0], one_type.bodies[0]));
  BOOST_TEST(!same_bits(together.bodies[1], one_type.bodies[1]));
}

BOOST_AUTO_TEST_CASE(coupled_types_conserve_the_energy_at_the_integrator_order) {
  const double T = 10;
  // (integrator, order, h, bound on the error at h/2)
  for (const auto& [integrator, order, h, bound] :
       {std::tuple{std::string("SIER2"), 2.0, 0.02, 0.02}, std::tuple{std::string("SIER4"), 4.0, 0.05, 1e-5}}) {
    const long steps = std::lround(T / h);
    const double e1 = energy_error(integrator, h, steps), e2 = energy_error(integrator, h / 2, 2 * steps);
    const double p = std::log2(e1 / e2);
    BOOST_TEST_MESSAGE(integrator << ": max |E - E0| " << e1 << " at h, " << e2 << " at h/2, order " << p);
    BOOST_TEST(p > order - 0.15);
    BOOST_TEST(p < order + 0.15);
    BOOST_TEST(e2 < bound);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // body_types_test
