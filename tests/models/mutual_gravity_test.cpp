// The mutual gravity of two rigid bodies (mutual_gravity.hpp) against independent expectations: order
// 0 is Newton's point masses; the force is −∂U/∂r and each torque −∂U/∂θ (U differentiated by central
// differences in long double, the bodies turned about inertial axes); r × F + M₁ + M₂ = 0 (the total
// angular momentum's conservation) to round-off; a sphere has no second-degree term; at order 4 the
// expansion of two clusters of point masses (their integrals summed directly) against the exact sum of
// their pairs' potentials, the error falling as the truncation says.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "point_clusters.hpp"
#include "random_seed.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/spin_orbit.hpp"
#include "rotlie/models/scenes/mutual_gravity.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(mutual_gravity_test)

using namespace rotlie::models;
using ld = long double;

namespace {

using rotlie::test::point_cluster;
using rotlie::test::random_cluster;
using rotlie::test::exact_cluster_potential;

struct pair_setup {
  gravitating_body<ld> b1, b2;
  mat3<ld> Q1, Q2;
  vec3<ld> r;
};

// Didymos-like proportions in units where G = 1: a flattened primary, an elongated secondary, a few
// primary radii apart, both turned arbitrarily.
pair_setup random_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const auto axis = [&] {
    vec3<ld> a{u(rng), u(rng), u(rng)};
    const ld n = std::sqrt(dot(a, a));
    return vec3<ld>{a[0] / n, a[1] / n, a[2] / n};
  };
  pair_setup p;
  p.b1 = ellipsoid_body<ld>(5.2L, 0.42L, 0.40L, 0.37L);
  p.b2 = ellipsoid_body<ld>(0.048L, 0.103L, 0.079L, 0.066L);
  p.Q1 = rotation<ld>(axis(), 3 * u(rng));
  p.Q2 = rotation<ld>(axis(), 3 * u(rng));
  const vec3<ld> d = axis();
  p.r = {1.2L * d[0], 1.2L * d[1], 1.2L * d[2]};
  return p;
}

ld norm(const vec3<ld>& v) { return std::sqrt(dot(v, v)); }


template <int K>
tensor3<ld, K> cluster_integral(const point_cluster& c) {
  tensor3<ld, K> t{};
  for (std::size_t i = 0; i < c.m.size(); ++i)
    for (std::size_t index = 0; index < t.size(); ++index) {
      ld product = c.m[i];
      for (std::size_t rest = index, slot = 0; slot < static_cast<std::size_t>(K); ++slot, rest /= 3) product *= c.x[i][rest % 3];
      t[index] += product;
    }
  return t;
}

gravitating_body<ld> cluster_body(const point_cluster& c) {
  gravitating_body<ld> b;
  for (const ld m : c.m) b.mass += m;
  mat3<ld> J;
  J.a = cluster_integral<2>(c);
  const ld trace = J(0, 0) + J(1, 1) + J(2, 2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.inertia(i, j) = (i == j ? trace : 0.0L) - J(i, j);
  b.third = cluster_integral<3>(c);
  b.fourth = cluster_integral<4>(c);
  b.degree = 4;
  return b;
}

gravitating_body<ld> lopsided_cluster(std::mt19937_64& rng, ld mass, ld size) { return cluster_body(random_cluster(rng, mass, size, 7)); }


}  // namespace

BOOST_AUTO_TEST_CASE(order_zero_is_newtons_point_masses) {
  std::mt19937_64 rng(rotlie::test::test_seed("order_zero_is_newtons_point_masses"));
  const auto p = random_pair(rng);
  const auto g = mutual_gravity_at(p.b1, p.Q1, p.b2, p.Q2, p.r, 1.0L, 0);
  const ld r = norm(p.r);
  BOOST_TEST(std::abs(g.U + p.b1.mass * p.b2.mass / r) <= 1e-16L * std::abs(g.U));
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(g.F[k] + p.b1.mass * p.b2.mass * p.r[k] / (r * r * r)) <= 1e-16L * norm(g.F));
  BOOST_TEST(norm(g.M1) == 0.0L);
  BOOST_TEST(norm(g.M2) == 0.0L);
}

BOOST_AUTO_TEST_CASE(force_and_torques_are_the_potentials_derivatives) {
  std::mt19937_64 rng(rotlie::test::test_seed("force_and_torques_are_the_potentials_derivatives"));
  const ld h = 1e-6L;
  for (int trial = 0; trial < 40; ++trial) {
    auto p = random_pair(rng);
    const int order = trial % 2 ? 4 : 2;
    if (trial % 4 == 3) p.b2 = lopsided_cluster(rng, 0.048L, 0.1L);  // third-degree integrals too
    const auto g = mutual_gravity_at(p.b1, p.Q1, p.b2, p.Q2, p.r, 1.0L, order);
    const auto U = [&](const vec3<ld>& r, const mat3<ld>& Q1, const mat3<ld>& Q2) {
      return mutual_gravity_at(p.b1, Q1, p.b2, Q2, r, 1.0L, order).U;
    };
    vec3<ld> F{}, M1{}, M2{};
    for (std::size_t k = 0; k < 3; ++k) {
      vec3<ld> e{};
      e[k] = 1;
      vec3<ld> plus = p.r, minus = p.r;
      plus[k] += h, minus[k] -= h;
      F[k] = -(U(plus, p.Q1, p.Q2) - U(minus, p.Q1, p.Q2)) / (2 * h);
      // a small turn of one body about the inertial axis e: Q → R(e, ±h) Q
      M1[k] = -(U(p.r, rotation<ld>(e, h) * p.Q1, p.Q2) - U(p.r, rotation<ld>(e, -h) * p.Q1, p.Q2)) / (2 * h);
      M2[k] = -(U(p.r, p.Q1, rotation<ld>(e, h) * p.Q2) - U(p.r, p.Q1, rotation<ld>(e, -h) * p.Q2)) / (2 * h);
    }
    for (std::size_t k = 0; k < 3; ++k) {
      BOOST_TEST(std::abs(F[k] - g.F[k]) <= 1e-9L * norm(g.F), "trial " << trial << ", F" << k);
      BOOST_TEST(std::abs(M1[k] - g.M1[k]) <= 1e-7L * norm(g.M1), "trial " << trial << ", M1 " << k << ": " << M1[k] << " against " << g.M1[k]);
      BOOST_TEST(std::abs(M2[k] - g.M2[k]) <= 1e-7L * norm(g.M2), "trial " << trial << ", M2 " << k << ": " << M2[k] << " against " << g.M2[k]);
    }
  }
}

// The expansion of two random clusters of 7 point masses (all integrals nonzero) against the exact
// sum over their 49 pairs: the error of order N is the first omitted degree's (a degree-n term falls as
// 1/r^(n+1)): 1/r³ at order 0 (the first degree vanishes about the centres), 1/r⁴ at order 2 (the
// third degree), 1/r⁶ at order 4 (the fifth), so doubling r divides it by 2³, 2⁴, 2⁶. The error is
// taken as the largest over 16 random configurations (attitudes and direction) at each distance: in
// one configuration the leading term can nearly vanish and the next ones, of either sign, show.
BOOST_AUTO_TEST_CASE(the_expansion_converges_to_the_exact_potential_of_point_clusters) {
  std::mt19937_64 rng(rotlie::test::test_seed("the_expansion_converges_to_the_exact_potential_of_point_clusters"));
  for (int trial = 0; trial < 3; ++trial) {
    const auto c1 = random_cluster(rng, 3.0L, 0.4L, 7), c2 = random_cluster(rng, 0.5L, 0.2L, 7);
    const auto b1 = cluster_body(c1), b2 = cluster_body(c2);
    std::vector<pair_setup> configurations;
    for (int k = 0; k < 16; ++k) configurations.push_back(random_pair(rng));  // attitudes and a direction
    for (const int order : {0, 2, 4}) {
      ld errors[2] = {0, 0};
      for (int k = 0; k < 2; ++k) {
        const ld scale = k == 0 ? 32.0L : 64.0L;
        for (const auto& p : configurations) {
          const vec3<ld> r{scale * p.r[0], scale * p.r[1], scale * p.r[2]};
          errors[k] = std::max(errors[k], std::abs(mutual_gravity_at(b1, p.Q1, b2, p.Q2, r, 1.0L, order).U - exact_cluster_potential(c1, p.Q1, c2, p.Q2, r)));
        }
      }
      const ld slope = std::log2(errors[0] / errors[1]);
      BOOST_TEST_MESSAGE("order " << order << ": largest error " << static_cast<double>(errors[0]) << " at r = 38.4, slope " << static_cast<double>(slope));
      const int expected = order == 0 ? 3 : order + 2;
      BOOST_TEST(std::abs(slope - expected) < 0.3, "trial " << trial << ", order " << order << ": slope " << slope);
    }
  }
}

// All three torque and force terms of order 4 balance: r × F + M₁ + M₂ = 0, in double as a run computes it.
BOOST_AUTO_TEST_CASE(the_total_angular_momentum_is_conserved) {
  std::mt19937_64 rng(rotlie::test::test_seed("the_total_angular_momentum_is_conserved"));
  const auto to_double = [](const auto& from, auto& to) {
    for (std::size_t i = 0; i < from.size(); ++i) to[i] = static_cast<double>(from[i]);
  };
  for (int trial = 0; trial < 40; ++trial) {
    auto q = random_pair(rng);
    const int order = trial % 2 ? 4 : 2;
    if (trial % 4 == 3) q.b1 = lopsided_cluster(rng, 5.2L, 0.4L);
    // in double, as a run computes it
    gravitating_body<double> b1, b2;
    b1.mass = static_cast<double>(q.b1.mass), b2.mass = static_cast<double>(q.b2.mass);
    b1.degree = b2.degree = 4;
    to_double(q.b1.inertia.a, b1.inertia.a), to_double(q.b2.inertia.a, b2.inertia.a);
    to_double(q.b1.third, b1.third), to_double(q.b2.third, b2.third);
    to_double(q.b1.fourth, b1.fourth), to_double(q.b2.fourth, b2.fourth);
    mat3<double> Q1, Q2;
    vec3<double> r;
    to_double(q.Q1.a, Q1.a), to_double(q.Q2.a, Q2.a), to_double(q.r, r);
    const auto g = mutual_gravity_at(b1, Q1, b2, Q2, r, 1.0, order);
    const auto rF = cross(r, g.F);
    const double scale = std::sqrt(dot(g.M1, g.M1)) + std::sqrt(dot(g.M2, g.M2)) + std::sqrt(dot(r, r)) * std::sqrt(dot(g.F, g.F));
    for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(rF[k] + g.M1[k] + g.M2[k]) <= 8e-16 * scale, "trial " << trial);
  }
}

BOOST_AUTO_TEST_CASE(a_sphere_has_no_second_degree_term) {
  const gravitating_body<ld> sphere{2.0L, ellipsoid_inertia<ld>(2.0L, 0.5L, 0.5L, 0.5L)}, other{0.3L, ellipsoid_inertia<ld>(0.3L, 0.2L, 0.1L, 0.05L)};
  const vec3<ld> r{0.3L, -1.1L, 0.4L};
  const auto Q = rotation<ld>({0, 0.6L, 0.8L}, 0.7L);
  // the sphere's term vanishes: only the other body's remains, and the sphere feels no torque
  const auto with_sphere = mutual_gravity_at(sphere, Q, other, Q, r, 1.0L, 2);
  const auto point_and_other = mutual_gravity_at(gravitating_body<ld>{2.0L, {}}, Q, other, Q, r, 1.0L, 2);
  BOOST_TEST(std::abs(with_sphere.U - point_and_other.U) <= 1e-17L * std::abs(with_sphere.U));
  // the torque's scale, 3 G m₂ I / r³, times the round-off of turning an isotropic tensor (Q I Qᵀ)
  const ld scale = 3 * other.mass * sphere.inertia(0, 0) / (norm(r) * norm(r) * norm(r));
  BOOST_TEST(norm(with_sphere.M1) <= 64 * std::numeric_limits<ld>::epsilon() * scale);
}

// Two ellipsoids on a near-circular mutual orbit integrated by the md engine's SIER2 (exact rotors):
// the total angular momentum Σ q × p + Q G to round-off over 20 orbits (each flow keeps it: the drift
// keeps q × p, the exact free rotation Q G, and a kick adds (r × F + M₁ + M₂) h/2 = 0), the energy
// error of second order in h (halving h divides it by about 4).
BOOST_AUTO_TEST_CASE(sier2_keeps_the_total_angular_momentum_and_is_of_order_two) {
  const double m1 = 5.2, m2 = 0.048, M = m1 + m2, R = 1.2;
  const auto moments = [](double m, double a, double b, double c) {
    const auto I = ellipsoid_inertia<double>(m, a, b, c);
    return vec3<double>{I(0, 0), I(1, 1), I(2, 2)};
  };
  const vec3<double> J1 = moments(m1, 0.42, 0.40, 0.37), J2 = moments(m2, 0.103, 0.079, 0.066);
  const full_two_body_gravity<double> gravity(m1, J1, m2, J2, 1.0, 2);
  const std::vector<body_kind<double>> kinds{{m1, J1, nullptr}, {m2, J2, nullptr}};
  const double n = std::sqrt(M / (R * R * R)), period = 2 * std::acos(-1.0) / n;
  const auto start = [&] {
    rigid_bodies_state<double> x;
    x.bodies.resize(2);
    x.bodies[0].q = {-m2 / M * R, 0, 0}, x.bodies[1].q = {m1 / M * R, 0, 0};
    const double mu = m1 * m2 / M;
    x.bodies[0].p = {0, -mu * n * R, 0}, x.bodies[1].p = {0, mu * n * R, 0};
    x.bodies[1].type = 1;
    x.bodies[0].rot.Q = rotation<double>({0.0, 0.6, 0.8}, 0.2);  // the primary tilted and spinning fast
    x.bodies[0].rot.G = {0.1 * J1[0], 0.2 * J1[1], 3 * n * J1[2]};
    x.bodies[1].rot.Q = mat3<double>::identity();  // the secondary synchronous
    x.bodies[1].rot.G = {0, 0, n * J2[2]};
    return x;
  };
  const auto total_L = [](const rigid_bodies_state<double>& x) {
    vec3<double> L{};
    for (const auto& b : x.bodies) {
      const auto orbital = cross(b.q, b.p), spin = b.rot.Q * b.rot.G;
      for (std::size_t k = 0; k < 3; ++k) L[k] += orbital[k] + spin[k];
    }
    return L;
  };
  double errors[2] = {0, 0};
  for (int refine = 0; refine < 2; ++refine) {
    const long steps_per_orbit = refine == 0 ? 200 : 400, orbits = 20;
    const double h = period / static_cast<double>(steps_per_orbit);
    with_md_integrator<double>(rotlie::test::splitting("SIER2"), kinds, gravity, unit_system<double>::natural(), [&](const auto& method) {
      auto x = start();
      const auto& sys = method.system();
      const double E0 = sys.energy(x);
      const auto L0 = total_L(x);
      double worst_L = 0;
      for (long k = 0; k < steps_per_orbit * orbits; ++k) {
        method.step(x, h);
        const auto L = total_L(x);
        for (std::size_t i = 0; i < 3; ++i) worst_L = std::max(worst_L, std::abs(L[i] - L0[i]) / std::sqrt(dot(L0, L0)));
        errors[refine] = std::max(errors[refine], std::abs(sys.energy(x) - E0) / std::abs(E0));
      }
      BOOST_TEST_MESSAGE(steps_per_orbit << " steps per orbit, " << orbits << " orbits: largest relative change of the total angular momentum "
                                         << worst_L << ", of the energy " << errors[refine]);
      // round-off only: a random walk of at most 64 ε per step (a splitting that did not conserve L
      // would change it at the size of the energy error, ~1e-7 here)
      const double steps = static_cast<double>(steps_per_orbit * orbits);
      BOOST_TEST(worst_L <= 64 * std::numeric_limits<double>::epsilon() * std::sqrt(steps));
      return 0;
    });
  }
  const double slope = std::log2(errors[0] / errors[1]);
  BOOST_TEST_MESSAGE("energy error slope between h and h/2: " << slope);
  BOOST_TEST(slope > 1.8);
  BOOST_TEST(slope < 2.2);
}

// The spin–orbit scene's torque (spin_orbit_tide: a point mass G M = 1 on a Kepler orbit) is the
// torque the pair gives the body when its partner is that point mass, along the orbit: two codes, one
// formula (MacCullagh's), to round-off.
BOOST_AUTO_TEST_CASE(the_spin_orbit_torque_is_the_pairs_with_a_point_mass) {
  const vec3<double> moments{0.8, 0.9, 1.0};
  const spin_orbit_tide<double> tide(moments, 0.1);
  mat3<double> I{};
  for (int k = 0; k < 3; ++k) I(k, k) = moments[static_cast<std::size_t>(k)];
  const gravitating_body<double> point{1.0, {}}, body{1e-9, I};  // the body's mass moves nothing here
  const auto Q = rotation<double>({0.3, -0.4, std::sqrt(0.75)}, 1.1);
  for (int j = 0; j < 12; ++j) {
    const double t = 0.55 * j;
    const auto o = tide.orbit().at(t);
    const vec3<double> r{o.r * o.cos_f, o.r * o.sin_f, 0};  // the body seen from the point mass
    std::vector<rigid_body_state<double>> bodies(1);
    bodies[0].rot.Q = Q;
    std::vector<vec3<double>> force(1), torque(1);
    tide.evaluate(bodies, force, torque, t);
    const auto g = mutual_gravity_at(point, mat3<double>::identity(), body, Q, r, 1.0, 2);
    const double size = std::sqrt(dot(torque[0], torque[0]));
    for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(g.M2[k] - torque[0][k]) <= 1e-14 * size, "t = " << t << ", component " << k);
  }
}

// The spin–orbit limit, in motion: a small body (size 1e-3 of the orbit, mass 1e-12 of its partner)
// about a point mass of G M = 1 on the scene's eccentric orbit, integrated as a full two-body problem
// by SIER4 with exact rotors, turns as the spin–orbit scene's body does under SIER4 (its orbit fixed):
// the attitudes after one orbit agree to the body's effect on the orbit, (size/r)² ~ 1e-6.
BOOST_AUTO_TEST_CASE(a_small_body_about_a_point_mass_is_the_spin_orbit_scene) {
  const double e = 0.1, eps = 1e-12, size2 = 1e-6;
  const vec3<double> moments{0.8, 0.9, 1.0};  // the scene's, C = 1
  const long steps = 2000;
  const double h = 2 * std::acos(-1.0) / static_cast<double>(steps);
  const auto start = spin_orbit_start<double>(moments, 0.3, 1.7, 0.2);
  // the spin–orbit scene
  const spin_orbit_tide<double> tide(moments, e);
  mat3<double> scene_Q;
  with_md_integrator<double>(rotlie::test::splitting("SIER4"), std::vector<body_kind<double>>{{1.0, moments, nullptr}}, tide,
                             unit_system<double>::natural(), [&](const auto& method) {
                               auto x = spin_orbit_state(start);
                               for (long k = 0; k < steps; ++k) method.step(x, h);
                               scene_Q = x.bodies[0].rot.Q;
                               return 0;
                             });
  // the pair: body 0 the point mass (a small sphere), body 1 the small body (its moments and momentum
  // scaled by eps·size²)
  const double m = eps, scale = eps * size2, M = 1 + m, mu = m / M;
  const vec3<double> small_moments{scale * moments[0], scale * moments[1], scale * moments[2]};
  const vec3<double> sphere{0.4 * size2, 0.4 * size2, 0.4 * size2};  // a uniform sphere: no second-degree term
  const full_two_body_gravity<double> gravity(1.0, sphere, m, small_moments, 1.0, 2);
  mat3<double> pair_Q;
  with_md_integrator<double>(rotlie::test::splitting("SIER4"), std::vector<body_kind<double>>{{1.0, sphere, nullptr}, {m, small_moments, nullptr}},
                             gravity, unit_system<double>::natural(), [&](const auto& method) {
                               rigid_bodies_state<double> x;
                               x.bodies.resize(2);
                               const double rp = 1 - e, vp = std::sqrt(M * (1 + e) / (1 - e));
                               x.bodies[0].q = {-m / M * rp, 0, 0}, x.bodies[1].q = {1 / M * rp, 0, 0};
                               x.bodies[0].p = {0, -mu * vp, 0}, x.bodies[1].p = {0, mu * vp, 0};
                               x.bodies[1].type = 1;
                               x.bodies[1].rot = start;
                               for (std::size_t k = 0; k < 3; ++k) x.bodies[1].rot.G[k] *= scale;
                               for (long k = 0; k < steps; ++k) method.step(x, h);
                               pair_Q = x.bodies[1].rot.Q;
                               return 0;
                             });
  const double d = distance(scene_Q, pair_Q);
  BOOST_TEST_MESSAGE("one orbit (e = 0.1, 2000 SIER4 steps): the attitudes of the scene and of the pair differ by " << d);
  BOOST_TEST(d <= 10 * size2);
}

BOOST_AUTO_TEST_CASE(an_unknown_order_is_refused) {
  const gravitating_body<double> b{1.0, {}};
  const auto I = mat3<double>::identity();
  BOOST_CHECK_THROW(mutual_gravity_at(b, I, b, I, vec3<double>{1, 0, 0}, 1.0, -2), std::invalid_argument);
  BOOST_CHECK_THROW(mutual_gravity_at(b, I, b, I, vec3<double>{1, 0, 0}, 1.0, max_gravity_order + 1), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(order_four_refuses_a_body_given_by_its_inertia_alone) {
  const gravitating_body<double> given_by_inertia{1.0, ellipsoid_inertia(1.0, 0.3, 0.2, 0.1)}, point{0.1, {}};
  const auto full = ellipsoid_body(1.0, 0.3, 0.2, 0.1);
  const auto I = mat3<double>::identity();
  BOOST_CHECK_THROW(mutual_gravity_at(given_by_inertia, I, full, I, vec3<double>{1, 0, 0}, 1.0, 4), std::invalid_argument);
  BOOST_CHECK_NO_THROW(mutual_gravity_at(full, I, point, I, vec3<double>{1, 0, 0}, 1.0, 4));
}

BOOST_AUTO_TEST_SUITE_END()  // mutual_gravity_test
