// What the torqued-body integrators conserve (vZS sections III–IV, Table I): with V = 0 the lab
// angular momentum L = Q G of each body, and in a field along z its z component (τ = μ × E ⟂ z, so
// the kicks keep L_z, and the free flight keeps L), to round-off growth for SIER and MRDL; SEJ4's
// approximate attitude does not (the paper's SEJ4 L_z errors of 1e-5 … 1e-3). And a step of h
// followed by one of −h returns to the start for the symmetric integrators, not for a Lie–Trotter.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "md_support.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(md_conservation_test)

using namespace rotlie;
using models::vec3;

namespace {

struct drift {
  double L = 0, Lz = 0;  ///< max over steps and bodies of |ΔL|/|L₀| and |ΔL_z|/|L₀|
};

template <class Potential>
drift lab_momentum_drift(const std::string& name, const Potential& potential, long steps) {
  const auto s0 = test::thermal_bodies<double>(3);
  drift d;
  auto watch = [&](long, double, const models::rigid_bodies_state<double>& x) {
    for (std::size_t n = 0; n < x.bodies.size(); ++n) {
      const vec3<double> a = models::lab_spin(x.bodies[n]), b = models::lab_spin(s0.bodies[n]);
      const double size = std::sqrt(models::dot(b, b));
      const vec3<double> diff{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
      d.L = std::max(d.L, std::sqrt(models::dot(diff, diff)) / size);
      d.Lz = std::max(d.Lz, std::abs(diff[2]) / size);
    }
  };
  auto s = s0;
  models::with_md_integrator<double>(rotlie::test::splitting(name), nullptr, test::water_mass<double>(),
                                     test::water_moments_real<double>(), potential, [&](const auto& m) {
                                       models::integrate(m, s, 4.0, steps, watch);
                                       return 0;
                                     });
  return d;
}

// Round-off growth allowed: one ε per free flight (each a product of rotations or an exact-flow
// evaluation, whose error is a few ε relative).
double allowed(const std::string& name, long steps) {
  const long flights = rotlie::test::splitting(name).tv_table == "PEFRL-TV" ? 4 : 1;
  return static_cast<double>(steps * flights) * DBL_EPSILON;
}

const char* const conserving[] = {"SIER2", "SIER4", "MRDL", "MRDL-reversed", "SIER4/RS4-S5-McLachlan:CBA", "SIER2/ABCBA4-SS3-Yoshida:ABC"};

}  // namespace

BOOST_AUTO_TEST_CASE(free_bodies_keep_their_lab_angular_momentum) {
  const long steps = 10000;  // 40 ps at 4 fs
  for (const char* name : conserving) {
    const auto d = lab_momentum_drift(name, models::zero_potential<double>{}, steps);
    BOOST_TEST_MESSAGE(name << ": max |ΔL|/|L| = " << d.L);
    BOOST_TEST(d.L < allowed(name, steps), name << " " << d.L);
  }
  // SEJ4 keeps |L| (exact G, orthogonal Q) but not the direction of L: its attitude is approximate
  const auto d = lab_momentum_drift("SEJ4", models::zero_potential<double>{}, steps);
  BOOST_TEST_MESSAGE("SEJ4: max |ΔL|/|L| = " << d.L);
  BOOST_TEST(d.L > 1e3 * allowed("SEJ4", steps));
}

BOOST_AUTO_TEST_CASE(a_field_along_z_keeps_l_z) {
  const long steps = 10000;
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  for (const char* name : conserving) {
    const auto d = lab_momentum_drift(name, scene, steps);
    BOOST_TEST_MESSAGE(name << ": max |ΔL_z|/|L| = " << d.Lz << " (|ΔL|/|L| = " << d.L << ": the field turns L)");
    BOOST_TEST(d.Lz < allowed(name, steps), name << " " << d.Lz);
    BOOST_TEST(d.L > 0.1, name);  // the torque is real
  }
  const auto d = lab_momentum_drift("SEJ4", scene, steps);
  BOOST_TEST_MESSAGE("SEJ4: max |ΔL_z|/|L| = " << d.Lz);
  BOOST_TEST(d.Lz > 1e3 * allowed("SEJ4", steps));
}

BOOST_AUTO_TEST_CASE(a_step_and_its_reverse_return_to_the_start) {
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  const auto s0 = test::thermal_bodies<double>(3);
  for (const char* name : {"SIER2", "SIER4", "MRDL", "SEJ4", "SIER4/RS4-S5-McLachlan:CBA", "SIER2/ABCBA2:BAC"}) {
    const auto there = test::run<double>(name, scene, s0, 4.0, 1);
    const double back = test::state_distance(test::run<double>(name, scene, there, -4.0, 1), s0);
    BOOST_TEST_MESSAGE(name << ": h then −h, distance " << back << " (one step moved " << test::state_distance(there, s0) << ")");
    BOOST_TEST(back < 1e-13, name << " " << back);  // ≈ 450 ε over three bodies
  }
  // the Lie–Trotter V(h) T(h) is not symmetric: its h, −h does not come back
  const auto trotter = schemes::parse_scheme_table(
      "format_version 1\nname VT\nsplit TV\nword VT\nsymmetric false\nstage V v 1\nstage T t 1\n");
  using system = models::torqued_rigid_bodies<double, models::dipole_in_field<double>, models::exact_free_rotation<double>>;
  const auto I = test::water_moments_real<double>();
  const models::composition<system> m(trotter, system(test::water_mass<double>(), I, scene, models::exact_free_rotation<double>(I)));
  auto s = s0;
  m.step(s, 4.0);
  m.step(s, -4.0);
  BOOST_TEST(test::state_distance(s, s0) > 1e-4);
}

BOOST_AUTO_TEST_SUITE_END()  // md_conservation_test
