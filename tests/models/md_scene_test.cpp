// The van Zon & Schofield scenes and experiments: the seeded generator, the water data against an
// independent rigid geometry, canonical initial conditions against equipartition, the dipole's
// energy against its closed form, and the experiments' measures against the orders they must show.
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/float128.hpp>

#include <cmath>
#include <numbers>

#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(md_scene_test)

using namespace rotlie::models;

BOOST_AUTO_TEST_CASE(the_generator_repeats_a_seed_and_separates_runs) {
  seeded_random a(7, 3), b(7, 3), c(7, 4), d(8, 3);
  int differ_run = 0, differ_seed = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next();
    BOOST_TEST(x == b.next());
    differ_run += x != c.next();
    differ_seed += x != d.next();
  }
  BOOST_TEST(differ_run == 1000);
  BOOST_TEST(differ_seed == 1000);
}

BOOST_AUTO_TEST_CASE(the_portable_logarithm_agrees_with_the_library_to_an_ulp_or_two) {
  seeded_random r(1);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::ldexp(r.uniform() + 1e-300, static_cast<int>(r.next() % 80) - 70);
    const double ours = detail::portable_log(x), library = std::log(x);
    BOOST_TEST(std::abs(ours - library) <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(library)));
  }
}

BOOST_AUTO_TEST_CASE(normals_have_the_first_four_moments_of_the_standard_normal) {
  seeded_random r(42);
  const int n = 400000;
  double m1 = 0, m2 = 0, m4 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal();
    m1 += x, m2 += x * x, m4 += x * x * x * x;
  }
  m1 /= n, m2 /= n, m4 /= n;
  // standard errors: 1/√n, √2/√n, √96/√n; five of them
  BOOST_TEST(std::abs(m1) < 5 / std::sqrt(n));
  BOOST_TEST(std::abs(m2 - 1) < 5 * std::sqrt(2.0 / n));
  BOOST_TEST(std::abs(m4 - 3) < 5 * std::sqrt(96.0 / n));
}

// The rigid TIP geometry (r_OH = 0.9572 Å, HOH = 104.52°, masses 15.9994 and 1.00794) gives moments
// within 0.2 % of E&K's and puts the C2 axis at the intermediate moment: an independent check of
// the unit conversion (10⁻⁴⁰ g cm² → g/mol·Å²) and of the dipole's axis.
BOOST_AUTO_TEST_CASE(water_moments_match_a_rigid_geometry_in_real_units) {
  const double r = 0.9572, half = 104.52 / 2 * std::numbers::pi / 180, mO = 15.9994, mH = 1.00794, M = mO + 2 * mH;
  const double y = r * std::cos(half), x = r * std::sin(half);  // C2 along y, the plane is x-y
  const double yc = 2 * mH * y / M;                             // centre of mass on the C2 axis
  const double Iy = 2 * mH * x * x;                             // about C2
  const double Ix = mO * yc * yc + 2 * mH * (y - yc) * (y - yc);  // in plane, perpendicular to C2
  const double Iz = Ix + Iy;                                    // normal to the plane
  const auto I = water::moments<double>();
  BOOST_TEST(std::abs(Ix / I[0] - 1) < 2e-3);
  BOOST_TEST(std::abs(Iy / I[water::c2_axis] - 1) < 2e-3);
  BOOST_TEST(std::abs(Iz / I[2] - 1) < 2e-3);
  BOOST_TEST(std::abs(M / water::mass<double>() - 1) < 1e-5);
  // the exact ratio of the E&K set, as LV state it
  BOOST_TEST(std::abs(I[0] / I[2] - 10220.0 / 29376) < 1e-15);
  BOOST_TEST(std::abs(I[1] / I[2] - 19187.0 / 29376) < 1e-15);
}

BOOST_AUTO_TEST_CASE(canonical_states_obey_equipartition_and_cover_the_rotations) {
  const free_water<double> scene;
  const double kT = 0.0019872067 * 297;  // kcal/mol
  const double mvv2e = 48.88821291 * 48.88821291;
  const int n = 20000;
  vec3<double> e{};
  double translational = 0;
  mat3<double> mean{};
  for (int k = 0; k < n; ++k) {
    const auto s = scene.initial(5, static_cast<std::uint64_t>(k)).bodies[0];
    for (std::size_t i = 0; i < 3; ++i) e[i] += mvv2e * s.rot.G[i] * s.rot.G[i] / scene.moments[i] / n;
    translational += mvv2e * dot(s.p, s.p) / scene.mass / n;
    const auto QtQ = transpose(s.rot.Q) * s.rot.Q;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) BOOST_TEST(std::abs(QtQ(i, j) - (i == j)) < 10 * std::numeric_limits<double>::epsilon());  // a few ε: three products per entry
    for (std::size_t i = 0; i < 9; ++i) mean.a[i] += s.rot.Q.a[i] / n;
  }
  // ⟨G_i²/I_i⟩ = k_B T per axis (relative standard error √(2/n) = 1 %), ⟨p²/m⟩ = 3 k_B T
  for (std::size_t i = 0; i < 3; ++i) BOOST_TEST(std::abs(e[i] / kT - 1) < 0.05);
  BOOST_TEST(std::abs(translational / (3 * kT) - 1) < 0.03);
  // a uniform rotation has ⟨Q⟩ = 0 (each entry has variance 1/3)
  for (std::size_t i = 0; i < 9; ++i) BOOST_TEST(std::abs(mean.a[i]) < 5 * std::sqrt(1.0 / 3 / n));
}

BOOST_AUTO_TEST_CASE(the_dipole_energy_and_torque_have_their_closed_forms) {
  const dipole_field<double> scene;
  auto x = scene.initial(1, 0);
  x.bodies[0].rot.Q = mat3<double>::identity();  // the C2 axis along lab y: V = 0, τ along −x
  std::vector<vec3<double>> f(1), tau(1);
  const double muE = 1.84 * 0.20819434 * 2.7e-4 * 23.060549;  // kcal/mol
  BOOST_TEST(std::abs(scene.potential.evaluate(x.bodies, f, tau)) < 1e-20);
  BOOST_TEST(std::abs(tau[0][0] - muE) < 1e-15);  // μ ŷ × E ẑ = μE x̂
  // C2 along z: V = −μE, no torque
  x.bodies[0].rot.Q = rotation<double>({1, 0, 0}, std::numbers::pi / 2);
  BOOST_TEST(std::abs(scene.potential.evaluate(x.bodies, f, tau) + muE) < 1e-15);
  BOOST_TEST(std::abs(tau[0][0]) + std::abs(tau[0][1]) + std::abs(tau[0][2]) < 1e-18);
}

BOOST_AUTO_TEST_CASE(tau_fit_recovers_a_linear_error_and_skips_saturated_samples) {
  free_water_result r;
  for (int j = 1; j <= 20; ++j) {
    r.t_ps.push_back(j);
    r.delta.push_back(j <= 10 ? j / (10 * 50.0) : 0.5);  // τ = 50 ps, then a saturated tail above 0.1
    r.reference_delta.push_back(1e-30);
  }
  fit_tau(r);
  BOOST_TEST(std::abs(r.tau_ps / 50 - 1) < 1e-14);
  BOOST_TEST(r.fitted_samples == 10);
}

namespace {
md_run_options options(const std::string& integrator, double h, double T, long runs) {
  md_run_options o;
  o.integrator = rotlie::test::splitting(integrator), o.h_fs = h, o.T_ps = T, o.runs = runs, o.seed = 3;
  return o;
}
}  // namespace

BOOST_AUTO_TEST_CASE(free_water_sier2_is_round_off_and_mrdl_second_order) {
  const free_water<double> scene;
  const auto sier2 = run_free_water(scene, options("SIER2", 8, 2, 4));
  BOOST_TEST(sier2.delta.back() < 1e-11);
  // MRDL (either axis order) is 2nd order: δ at fixed t scales as h², so τ(h/2)/τ(h) = 4
  for (const char* name : {"MRDL", "MRDL-reversed"}) {
    const auto coarse = run_free_water(scene, options(name, 2, 1, 20));
    const auto fine = run_free_water(scene, options(name, 1, 1, 20));
    BOOST_TEST_CONTEXT(name) BOOST_TEST(std::abs(fine.tau_ps / coarse.tau_ps / 4 - 1) < 0.1);
  }
  // a 4th-order free rotor: 16
  const auto coarse = run_free_water(scene, options("SIER2/RS4-S5-McLachlan:CBA", 8, 4, 20));
  const auto fine = run_free_water(scene, options("SIER2/RS4-S5-McLachlan:CBA", 4, 4, 20));
  BOOST_TEST(std::abs(fine.tau_ps / coarse.tau_ps / 16 - 1) < 0.15);
}

BOOST_AUTO_TEST_CASE(dipole_energy_error_has_each_integrators_order_and_lz_is_kept) {
  const dipole_field<double> scene;
  // SIER2: ΔH/ΔV ∝ h² (the splitting of T and V is its only error)
  const auto a = run_dipole_field(scene, options("SIER2", 4, 10, 10)), b = run_dipole_field(scene, options("SIER2", 2, 10, 10));
  BOOST_TEST(std::abs(a.dH.mean / b.dH.mean / 4 - 1) < 0.1);
  // SIER4: ∝ h⁴
  const auto c = run_dipole_field(scene, options("SIER4", 8, 10, 10)), d = run_dipole_field(scene, options("SIER4", 4, 10, 10));
  BOOST_TEST(std::abs(c.dH.mean / d.dH.mean / 16 - 1) < 0.2);
  // L_z: exactly conserved by SIER2 and MRDL, so round-off only
  for (const auto* r : {&a, &b, &c, &d}) BOOST_TEST(r->dLz.mean < 1e-11);
  BOOST_TEST(run_dipole_field(scene, options("MRDL", 4, 10, 10)).dLz.mean < 1e-11);
  BOOST_TEST(a.f == 1);
  BOOST_TEST(c.f == 4);
}

BOOST_AUTO_TEST_CASE(the_same_seed_gives_the_same_numbers_in_every_scalar) {
  const auto o = options("SIER2", 4.2, 2, 3);
  const auto a = run_dipole_field(dipole_field<double>{}, o), b = run_dipole_field(dipole_field<double>{}, o);
  BOOST_TEST(a.dH_over_dV_percent == b.dH_over_dV_percent);  // bit for bit
  BOOST_TEST(a.dLz_over_Lz == b.dLz_over_Lz);
  // float128 starts from the same draws: the same energy error to the accuracy of double's ΔH
  const auto q = run_dipole_field(dipole_field<boost::multiprecision::float128>{}, o);
  for (std::size_t i = 0; i < a.dH_over_dV_percent.size(); ++i)
    BOOST_TEST(std::abs(q.dH_over_dV_percent[i] / a.dH_over_dV_percent[i] - 1) < 1e-6);
}

BOOST_AUTO_TEST_CASE(non_finite_dipole_or_field_is_refused) {
  BOOST_CHECK_THROW(dipole_field<double>("nan", "2.7"), std::invalid_argument);
  BOOST_CHECK_THROW(dipole_field<double>("1.84", "inf"), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // md_scene_test
