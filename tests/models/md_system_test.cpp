// The torqued-body system and its integrator registry: names and refusals, the cost f, the force
// cache (f evaluations per step, the cached forces equal to fresh ones), a restart bit-identical,
// and the dipole potential's torque against the derivative of its energy.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "md_support.hpp"
#include "rotlie/models/free_rigid_body.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(md_system_test)

using namespace rotlie;
using models::vec3;

BOOST_AUTO_TEST_CASE(an_integrator_from_its_parts) {
  // the names are parsed on the library floor (tests/runs/method_registry_test); here the parts
  const auto sier4 = models::md_integrator_of("SIER4", "PEFRL-TV", "exact");
  BOOST_TEST((!sier4.table_rotor() && sier4.rotor == "exact" && sier4.f == 4));
  const auto mrdl = models::md_integrator_of("MRDL", "Strang-TV", models::mrdl_rotor_table);
  BOOST_TEST((mrdl.table_rotor() && mrdl.rotor_table == "ABCBA2:ABC" && mrdl.f == 1));  // DLM's order 1-2-3-2-1, LAMMPS's NO_SQUISH map
  BOOST_TEST(std::string(models::mrdl_reversed_rotor_table) == "ABCBA2:CBA");  // 3-2-1-2-3, full step on the smallest moment
  BOOST_TEST(models::md_integrator_of("SEJ4", "Strang-TV", "sej4").rotor == "sej4");
  BOOST_TEST(models::md_integrator_of("SIER6", "KahanLi6-TV", "exact").f == 9);
  BOOST_TEST((models::closed_form_rotor_names() == std::vector<std::string>{"exact", "sej4"}));
}

BOOST_AUTO_TEST_CASE(unresolved_and_wrong_tables_are_refused) {
  const auto scene = test::dipole_scene<double>(0.5);
  const auto run_with = [&](const std::string& tv, const std::string& rotor) {
    models::with_md_integrator<double>(models::md_integrator_of(tv + "/" + rotor, tv, rotor), nullptr, 18.0, test::water_moments_real<double>(),
                                       scene, [](const auto&) { return 0; });
  };
  BOOST_CHECK_THROW(run_with("PEFRL-TV", "P1:BAC:5"), std::invalid_argument);  // dedicated: the caller solves it
  BOOST_CHECK_THROW(run_with("Strang-TV", "ABCBA2:XYZ"), std::invalid_argument);
  BOOST_CHECK_NO_THROW(run_with("Strang-TV", "RSR2:BAC"));
  // a TV table cannot drive the free body, a free-body table cannot drive the torqued system
  BOOST_CHECK_THROW(models::table_rotor<double>(*schemes::reference_scheme("Strang-TV"), vec3<double>{1, 2, 3}),
                    std::invalid_argument);
  using system = models::torqued_rigid_bodies<double, models::dipole_in_field<double>, models::exact_free_rotation<double>>;
  const vec3<double> I = test::water_moments_real<double>();
  BOOST_CHECK_THROW(models::composition<system>(*schemes::reference_scheme("ABCBA2"), system(18.0, I, scene, models::exact_free_rotation<double>(I))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(system(0.0, I, scene, models::exact_free_rotation<double>(I)), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK_THROW(models::dipole_in_field<double>(nan, 1, {0, 0, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(models::dipole_in_field<double>(0.38, 1, {0, nan, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(models::dipole_in_field<double>(0.38, 3, {0, 0, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_force_cache_costs_f_per_step_and_is_never_stale) {
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  for (const char* name : {"SIER2", "SIER4", "MRDL", "SEJ4"}) {
    const auto spec = rotlie::test::splitting(name);
    models::with_md_integrator<double>(spec, nullptr, test::water_mass<double>(), test::water_moments_real<double>(), scene, [&](const auto& m) {
      BOOST_TEST(m.cost() == spec.f, name);
      auto s = test::thermal_bodies<double>(2);
      const long steps = 25;
      long checked = 0;
      auto fresh_forces = [&](long, double, const models::rigid_bodies_state<double>& x) {
        // after a step the last kick's forces are cached, and they are those of the configuration now
        BOOST_TEST(x.forces_current);
        std::vector<vec3<double>> f(x.bodies.size()), tau(x.bodies.size());
        const double V = scene.evaluate(x.bodies, f, tau);
        BOOST_TEST((V == x.potential && f == x.force && tau == x.torque), name);
        ++checked;
      };
      models::integrate(m, s, 2.0, steps, fresh_forces);
      BOOST_TEST(checked == steps);
      BOOST_TEST(s.force_evaluations == steps * spec.f + 1, name << ": " << s.force_evaluations);  // + the first step's first kick
    });
  }
  // V = 0: no kick evaluates anything
  const auto s = test::run<double>("SIER4", models::zero_potential<double>{}, test::thermal_bodies<double>(2), 2.0, 10);
  BOOST_TEST(s.force_evaluations == 0);
}

BOOST_AUTO_TEST_CASE(a_restart_from_a_copied_state_is_bit_identical) {
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  for (const char* name : {"SIER2", "SIER4", "MRDL", "SEJ4", "SIER4/RS4-S5-McLachlan:CBA"}) {
    const auto s0 = test::thermal_bodies<double>(3);
    const auto whole = test::run<double>(name, scene, s0, 3.0, 80);
    const auto half = test::run<double>(name, scene, s0, 3.0, 40);
    const auto resumed = test::run<double>(name, scene, half, 3.0, 40);
    // a saved state without its force cache (positions, momenta, attitudes only) resumes identically too
    auto bare = half;
    bare.force.clear();
    bare.torque.clear();
    bare.forces_current = false;
    const auto from_bare = test::run<double>(name, scene, bare, 3.0, 40);
    bool same = true, same_bare = true;
    for (std::size_t n = 0; n < whole.bodies.size(); ++n) {
      const auto &a = whole.bodies[n], &b = resumed.bodies[n], &c = from_bare.bodies[n];
      same = same && a.q == b.q && a.p == b.p && a.rot.Q.a == b.rot.Q.a && a.rot.G == b.rot.G;
      same_bare = same_bare && a.q == c.q && a.p == c.p && a.rot.Q.a == c.rot.Q.a && a.rot.G == c.rot.G;
    }
    BOOST_TEST(same, name);
    BOOST_TEST(same_bare, name);
  }
}

BOOST_AUTO_TEST_CASE(the_dipole_torque_is_minus_the_derivative_of_its_energy) {
  // V(R(u, ε) Q): dV/dε at 0 = −τ·u for a small lab rotation about u (central differences, long double)
  using L = long double;
  const auto scene = test::dipole_scene<L>(L(0.3));
  auto s = test::thermal_bodies<L>(1);
  std::vector<vec3<L>> f(1), tau(1);
  const L V0 = scene.evaluate(s.bodies, f, tau);
  // V = −μ·E exactly: μ = 1.84 D · qe2f along Q's column 1
  const L mu = L(184) / 100 * models::real_units::debye<L>() * models::real_units::qe2f<L>();
  BOOST_TEST(static_cast<double>(std::fabs(V0 + mu * s.bodies[0].rot.Q(2, 1) * L(0.3))) < 1e-17);
  BOOST_TEST((f[0] == vec3<L>{0, 0, 0}));
  BOOST_TEST(tau[0][2] == 0.0L);  // τ ⟂ E ∥ z, exactly
  for (const vec3<L>& u : {vec3<L>{1, 0, 0}, vec3<L>{0, 1, 0}, vec3<L>{0.6L, 0, 0.8L}}) {
    const L eps = 1e-6L;
    auto plus = s.bodies, minus = s.bodies;
    plus[0].rot.Q = models::rotation(u, eps) * s.bodies[0].rot.Q;
    minus[0].rot.Q = models::rotation(u, -eps) * s.bodies[0].rot.Q;
    const L dV = (scene.evaluate(plus, f, tau) - scene.evaluate(minus, f, tau)) / (2 * eps);
    scene.evaluate(s.bodies, f, tau);
    BOOST_TEST(static_cast<double>(std::fabs(dV + models::dot(tau[0], u))) < 1e-9);
  }
}

BOOST_AUTO_TEST_CASE(real_units_are_lammps_constants) {
  BOOST_TEST(models::real_units::mvv2e<double>() == 48.88821291 * 48.88821291);
  BOOST_TEST(models::real_units::ftm2v<double>() * models::real_units::mvv2e<double>() == 1.0);
  BOOST_TEST(models::real_units::boltz<double>() == 0.0019872067);
  BOOST_TEST(models::real_units::qqr2e<double>() == 332.06371);
  BOOST_TEST(models::real_units::qe2f<double>() == 23.060549);
  BOOST_TEST(models::real_units::debye<double>() == 0.20819434);
  // kinetic energy: mvv2e (p²/2m + Σ G²/2I)
  using system = models::torqued_rigid_bodies<double, models::zero_potential<double>, models::exact_free_rotation<double>>;
  const vec3<double> I{1, 2, 3};
  const system sys(2.0, I, {}, models::exact_free_rotation<double>(I));
  models::rigid_bodies_state<double> s;
  s.bodies.resize(1);
  s.bodies[0].p = {2, 0, 0};
  s.bodies[0].rot.G = {1, 2, 3};
  BOOST_TEST(sys.kinetic_energy(s) == models::real_units::mvv2e<double>() * (1.0 + 1.5 + 1.5), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(a_state_handed_to_another_potential_does_not_keep_the_old_forces) {
  using system = models::torqued_rigid_bodies<double, models::dipole_in_field<double>, models::exact_free_rotation<double>>;
  const auto I = test::water_moments_real<double>();
  const auto strong = test::dipole_scene<double>(test::strong_field<double>());
  const auto weak = test::dipole_scene<double>(test::strong_field<double>() / 10);
  const system a(test::water_mass<double>(), I, strong, models::exact_free_rotation<double>(I));
  const system b(test::water_mass<double>(), I, weak, models::exact_free_rotation<double>(I));
  auto s = test::thermal_bodies<double>(3);
  a.ensure_forces(s);
  BOOST_TEST_REQUIRE(s.forces_current);
  std::vector<vec3<double>> f(s.bodies.size()), tau(s.bodies.size());
  const double V_weak = weak.evaluate(s.bodies, f, tau);
  BOOST_TEST_REQUIRE(V_weak != s.potential);  // the two potentials differ here
  BOOST_TEST(b.potential_energy(s) == V_weak);
  b.ensure_forces(s);
  BOOST_TEST((s.potential == V_weak && s.force == f && s.torque == tau));
  // a copy of a system shares its potential, and so its cache
  const system b_copy = b;
  const long before = s.force_evaluations;
  b_copy.ensure_forces(s);
  BOOST_TEST(s.force_evaluations == before);
}

BOOST_AUTO_TEST_SUITE_END()  // md_system_test
