// The mutual gravity at any order (mutual_gravity_series.hpp) against independent expectations: its
// ∂^α(1/r) against the closed form of the written-out path; at orders 0, 2 and 4 the written-out path's
// values (two codes, one expansion); at orders 3 and 5 to 8 the force and torques as central
// differences of U, r × F + M₁ + M₂ = 0 to round-off in double, and the expansion of two clusters of
// point masses against the exact sum of their pairs' potentials, the error falling as the first omitted
// degree says; the ellipsoid's moments against the ball's ⟨r^2n⟩ = 3/(2n+3).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "point_clusters.hpp"
#include "random_seed.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/mutual_gravity.hpp"
#include "rotlie/models/scenes/spin_orbit.hpp"

BOOST_AUTO_TEST_SUITE(mutual_gravity_series_test)

using namespace rotlie::models;
using ld = long double;

namespace {

using rotlie::test::point_cluster;
using rotlie::test::random_cluster;
using rotlie::test::exact_cluster_potential;

ld norm(const vec3<ld>& v) { return std::sqrt(dot(v, v)); }

vec3<ld> random_axis(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  vec3<ld> a{u(rng), u(rng), u(rng)};
  const ld n = norm(a);
  return {a[0] / n, a[1] / n, a[2] / n};
}


// the cluster's integrals to `degree`: the tensors to 4 summed on full indices, the moments on monomials
gravitating_body<ld> cluster_body(const point_cluster& c, int degree) {
  gravitating_body<ld> b;
  mat3<ld> J{};
  for (std::size_t i = 0; i < c.m.size(); ++i) {
    b.mass += c.m[i];
    for (std::size_t p = 0; p < 3; ++p)
      for (std::size_t q = 0; q < 3; ++q) {
        J.a[3 * p + q] += c.m[i] * c.x[i][p] * c.x[i][q];
        for (std::size_t s = 0; s < 3; ++s) {
          b.third[9 * p + 3 * q + s] += c.m[i] * c.x[i][p] * c.x[i][q] * c.x[i][s];
          for (std::size_t t = 0; t < 3; ++t) b.fourth[27 * p + 9 * q + 3 * s + t] += c.m[i] * c.x[i][p] * c.x[i][q] * c.x[i][s] * c.x[i][t];
        }
      }
  }
  const ld trace = J(0, 0) + J(1, 1) + J(2, 2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.inertia(i, j) = (i == j ? trace : 0.0L) - J(i, j);
  b.degree = degree;
  if (degree > 4) {
    b.moments.assign(static_cast<std::size_t>(monomials_up_to(degree)), 0.0L);
    const auto& table = monomial_table::get();
    for (std::size_t k = 0; k < b.moments.size(); ++k)
      for (std::size_t i = 0; i < c.m.size(); ++i) {
        ld product = c.m[i];
        for (std::size_t axis = 0; axis < 3; ++axis)
          for (int p = 0; p < table.exponents[k][axis]; ++p) product *= c.x[i][axis];
        b.moments[k] += product;
      }
  }
  return b;
}


struct configuration {
  mat3<ld> Q1, Q2;
  vec3<ld> r;
};

configuration random_configuration(std::mt19937_64& rng, ld distance) {
  std::uniform_real_distribution<double> u(-1, 1);
  const auto d = random_axis(rng);
  return {rotation<ld>(random_axis(rng), 3 * u(rng)), rotation<ld>(random_axis(rng), 3 * u(rng)), {distance * d[0], distance * d[1], distance * d[2]}};
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_derivatives_of_the_inverse_distance_are_the_closed_forms) {
  const vec3<ld> x{0.7L, -1.3L, 0.4L};
  std::vector<ld> D(static_cast<std::size_t>(monomials_up_to(5)));
  series_detail::inverse_distance_derivatives(x, 5, D.data());
  const ld inverse_r = 1 / norm(x);
  const auto check = [&](const auto& closed, int n) {
    for (std::size_t index = 0; index < closed.size(); ++index) {
      int count[3] = {0, 0, 0};
      for (std::size_t rest = index, slot = 0; slot < static_cast<std::size_t>(n); ++slot, rest /= 3) ++count[rest % 3];
      const ld value = D[static_cast<std::size_t>(monomial_index(count[0], count[1], count[2]))];
      BOOST_TEST(std::abs(value - closed[index]) <= 1e-17L * (1 + std::abs(closed[index])), "degree " << n << ", component " << index);
    }
  };
  check(gravity_detail::inverse_distance_derivative<ld, 1>(x, inverse_r), 1);
  check(gravity_detail::inverse_distance_derivative<ld, 2>(x, inverse_r), 2);
  check(gravity_detail::inverse_distance_derivative<ld, 3>(x, inverse_r), 3);
  check(gravity_detail::inverse_distance_derivative<ld, 4>(x, inverse_r), 4);
  check(gravity_detail::inverse_distance_derivative<ld, 5>(x, inverse_r), 5);
  // and Laplace's equation at degree 9: Σ_i D_{α+2e_i} = 0
  std::vector<ld> high(static_cast<std::size_t>(monomials_up_to(9)));
  series_detail::inverse_distance_derivatives(x, 9, high.data());
  const auto& table = monomial_table::get();
  for (int i = first_monomial(7); i < first_monomial(8); ++i) {
    const auto& e = table.exponents[static_cast<std::size_t>(i)];
    const ld laplacian = high[static_cast<std::size_t>(monomial_index(e[0] + 2, e[1], e[2]))] + high[static_cast<std::size_t>(monomial_index(e[0], e[1] + 2, e[2]))] +
                         high[static_cast<std::size_t>(monomial_index(e[0], e[1], e[2] + 2))];
    const ld scale = std::abs(high[static_cast<std::size_t>(monomial_index(e[0] + 2, e[1], e[2]))]) + 1;
    BOOST_TEST(std::abs(laplacian) <= 1e-16L * scale, "monomial " << i);
  }
}

// Two codes for one expansion: the series against the written-out tensors at orders 0, 2 and 4, with
// and without the point masses' term.
BOOST_AUTO_TEST_CASE(the_series_is_the_written_out_expansion_at_orders_0_2_and_4) {
  std::mt19937_64 rng(rotlie::test::test_seed("the_series_is_the_written_out_expansion_at_orders_0_2_and_4"));
  for (int trial = 0; trial < 24; ++trial) {
    const auto b1 = cluster_body(random_cluster(rng, 5.2L, 0.4L, 7), 4), b2 = cluster_body(random_cluster(rng, 0.05L, 0.1L, 7), 4);
    const auto p = random_configuration(rng, 1.2L);
    for (const int order : {0, 2, 4})
      for (const bool point_masses : {true, false}) {
        const auto fast = mutual_gravity_written_out(b1, p.Q1, b2, p.Q2, p.r, 1.0L, order, point_masses);
        mutual_gravity<ld> series;
        mutual_gravity_series(b1, p.Q1, b2, p.Q2, p.r, 1.0L, order, point_masses, series.U, series.F, series.M1, series.M2);
        const ld scale = 1e-17L;
        BOOST_TEST(std::abs(series.U - fast.U) <= scale * (std::abs(fast.U) + 1e-3L), "order " << order);
        for (std::size_t k = 0; k < 3; ++k) {
          BOOST_TEST(std::abs(series.F[k] - fast.F[k]) <= scale * (norm(fast.F) + 1e-3L), "order " << order << ", F" << k);
          BOOST_TEST(std::abs(series.M1[k] - fast.M1[k]) <= 1e-16L * (norm(fast.M1) + 1e-6L), "order " << order << ", M1 " << k);
          BOOST_TEST(std::abs(series.M2[k] - fast.M2[k]) <= 1e-16L * (norm(fast.M2) + 1e-6L), "order " << order << ", M2 " << k);
        }
      }
  }
}

BOOST_AUTO_TEST_CASE(force_and_torques_are_the_potentials_derivatives_at_every_order) {
  std::mt19937_64 rng(rotlie::test::test_seed("force_and_torques_are_the_potentials_derivatives_at_every_order"));
  const ld h = 1e-6L;
  for (int order = 1; order <= 10; ++order)
    for (int trial = 0; trial < 4; ++trial) {
      const auto b1 = cluster_body(random_cluster(rng, 5.2L, 0.4L, 9), 10), b2 = cluster_body(random_cluster(rng, 0.05L, 0.1L, 9), 10);
      const auto p = random_configuration(rng, 1.2L);
      const auto g = mutual_gravity_at(b1, p.Q1, b2, p.Q2, p.r, 1.0L, order);
      const auto U = [&](const vec3<ld>& r, const mat3<ld>& Q1, const mat3<ld>& Q2) { return mutual_gravity_at(b1, Q1, b2, Q2, r, 1.0L, order).U; };
      vec3<ld> F{}, M1{}, M2{};
      for (std::size_t k = 0; k < 3; ++k) {
        vec3<ld> e{};
        e[k] = 1;
        vec3<ld> plus = p.r, minus = p.r;
        plus[k] += h, minus[k] -= h;
        F[k] = -(U(plus, p.Q1, p.Q2) - U(minus, p.Q1, p.Q2)) / (2 * h);
        M1[k] = -(U(p.r, rotation<ld>(e, h) * p.Q1, p.Q2) - U(p.r, rotation<ld>(e, -h) * p.Q1, p.Q2)) / (2 * h);
        M2[k] = -(U(p.r, p.Q1, rotation<ld>(e, h) * p.Q2) - U(p.r, p.Q1, rotation<ld>(e, -h) * p.Q2)) / (2 * h);
      }
      // the differences' round-off, ε |U| / h ~ 1e-14 |U|, bounds what a vanishing torque (order 1) can show
      const ld floor = 1e-12L * std::abs(g.U);
      for (std::size_t k = 0; k < 3; ++k) {
        BOOST_TEST(std::abs(F[k] - g.F[k]) <= 1e-9L * norm(g.F), "order " << order << ", F" << k);
        BOOST_TEST(std::abs(M1[k] - g.M1[k]) <= 1e-7L * norm(g.M1) + floor, "order " << order << ", M1 " << k << ": " << M1[k] << " against " << g.M1[k]);
        BOOST_TEST(std::abs(M2[k] - g.M2[k]) <= 1e-7L * norm(g.M2) + floor, "order " << order << ", M2 " << k << ": " << M2[k] << " against " << g.M2[k]);
      }
    }
}

// r × F + M₁ + M₂ = 0 in double, as a run computes it, at orders 3 and 5 to 10.
BOOST_AUTO_TEST_CASE(the_total_angular_momentum_is_conserved_at_every_order) {
  std::mt19937_64 rng(rotlie::test::test_seed("the_total_angular_momentum_is_conserved_at_every_order"));
  for (const int order : {3, 5, 6, 7, 8, 9, 10})
    for (int trial = 0; trial < 8; ++trial) {
      const auto c1 = cluster_body(random_cluster(rng, 5.2L, 0.4L, 9), 10), c2 = cluster_body(random_cluster(rng, 0.05L, 0.1L, 9), 10);
      const auto to_double = [](const gravitating_body<ld>& from) {
        gravitating_body<double> to;
        to.mass = static_cast<double>(from.mass);
        for (std::size_t i = 0; i < 9; ++i) to.inertia.a[i] = static_cast<double>(from.inertia.a[i]);
        for (std::size_t i = 0; i < to.third.size(); ++i) to.third[i] = static_cast<double>(from.third[i]);
        for (std::size_t i = 0; i < to.fourth.size(); ++i) to.fourth[i] = static_cast<double>(from.fourth[i]);
        for (const ld x : from.moments) to.moments.push_back(static_cast<double>(x));
        to.degree = from.degree;
        return to;
      };
      const auto b1 = to_double(c1), b2 = to_double(c2);
      const auto p = random_configuration(rng, 1.2L);
      mat3<double> Q1, Q2;
      vec3<double> r;
      for (std::size_t i = 0; i < 9; ++i) Q1.a[i] = static_cast<double>(p.Q1.a[i]), Q2.a[i] = static_cast<double>(p.Q2.a[i]);
      for (std::size_t i = 0; i < 3; ++i) r[i] = static_cast<double>(p.r[i]);
      const auto g = mutual_gravity_at(b1, Q1, b2, Q2, r, 1.0, order);
      const auto rF = cross(r, g.F);
      const double scale = std::sqrt(dot(g.M1, g.M1)) + std::sqrt(dot(g.M2, g.M2)) + std::sqrt(dot(r, r)) * std::sqrt(dot(g.F, g.F));
      for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(rF[k] + g.M1[k] + g.M2[k]) <= 8e-16 * scale, "order " << order << ", trial " << trial);
    }
}

// Orders 5 to 8 against two random clusters of 9 point masses (every degree present): the error of
// order N is the first omitted degree's, N + 1, whose term falls as 1/r^(N+2): doubling r from 9.6 to
// 19.2 divides it by 2^7, 2^8, 2^9, 2^10. The largest error over 16 configurations at each distance (in
// one of them the leading omitted term can nearly vanish).
BOOST_AUTO_TEST_CASE(orders_5_to_8_converge_to_the_exact_potential_of_point_clusters) {
  std::mt19937_64 rng(rotlie::test::test_seed("orders_5_to_8_converge_to_the_exact_potential_of_point_clusters"));
  for (int trial = 0; trial < 3; ++trial) {
    const auto c1 = random_cluster(rng, 3.0L, 0.4L, 9), c2 = random_cluster(rng, 0.5L, 0.2L, 9);
    const auto b1 = cluster_body(c1, 8), b2 = cluster_body(c2, 8);
    std::vector<configuration> configurations;
    for (int k = 0; k < 16; ++k) configurations.push_back(random_configuration(rng, 1.2L));
    for (const int order : {5, 6, 7, 8}) {
      ld errors[2] = {0, 0};
      for (int k = 0; k < 2; ++k) {
        const ld scale = k == 0 ? 8.0L : 16.0L;
        for (const auto& p : configurations) {
          const vec3<ld> r{scale * p.r[0], scale * p.r[1], scale * p.r[2]};
          errors[k] = std::max(errors[k], std::abs(mutual_gravity_at(b1, p.Q1, b2, p.Q2, r, 1.0L, order).U - exact_cluster_potential(c1, p.Q1, c2, p.Q2, r)));
        }
      }
      const ld slope = std::log2(errors[0] / errors[1]);
      BOOST_TEST_MESSAGE("order " << order << ": largest error " << static_cast<double>(errors[0]) << " at r = 9.6, slope " << static_cast<double>(slope));
      BOOST_TEST(std::abs(slope - (order + 2)) < 0.3, "trial " << trial << ", order " << order << ": slope " << slope);
    }
  }
}

// The unit ball's moments: ∫ (x² + y² + z²)^n dm = M · 3/(2n + 3), a sum of its monomial moments with
// the multinomial weights n!/(i! j! k!) (an identity the closed form does not use); degree 4 as the tensors.
BOOST_AUTO_TEST_CASE(the_ellipsoids_moments_are_the_balls_scaled) {
  const auto ball = ellipsoid_moments<ld>(2.0L, 1.0L, 1.0L, 1.0L, 12);
  const auto& table = monomial_table::get();
  for (int n = 0; n <= 6; ++n) {
    ld sum = 0;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        ld multinomial = 1;
        for (int q = 2; q <= n; ++q) multinomial *= q;
        for (const int p : {i, j, k})
          for (int q = 2; q <= p; ++q) multinomial /= q;
        sum += multinomial * ball[static_cast<std::size_t>(monomial_index(2 * i, 2 * j, 2 * k))];
      }
    BOOST_TEST(std::abs(sum - 2.0L * 3 / (2 * n + 3)) <= 1e-18L, "n = " << n);
  }
  // an ellipsoid's moments are the ball's scaled by a^a b^b c^c
  const auto e = ellipsoid_moments<ld>(2.0L, 0.5L, 0.3L, 0.2L, 8);
  for (std::size_t i = 0; i < e.size(); ++i) {
    const auto& x = table.exponents[i];
    const ld expected = ball[i] * std::pow(0.5L, x[0]) * std::pow(0.3L, x[1]) * std::pow(0.2L, x[2]);
    BOOST_TEST(std::abs(e[i] - expected) <= 1e-18L * std::abs(expected) + 1e-30L, "monomial " << i);
  }
  // to degree 4 the tensors' (ellipsoid_body)
  const auto body = ellipsoid_body<ld>(2.0L, 0.5L, 0.3L, 0.2L);
  std::vector<ld> from_tensors(static_cast<std::size_t>(monomials_up_to(4)));
  body_moments(body, 4, from_tensors.data());
  for (std::size_t i = 0; i < from_tensors.size(); ++i) BOOST_TEST(std::abs(from_tensors[i] - e[i]) <= 1e-18L, "monomial " << i);
}

BOOST_AUTO_TEST_CASE(orders_beyond_the_bodies_integrals_or_the_series_are_refused) {
  const auto four = ellipsoid_body(1.0, 0.3, 0.2, 0.1), eight = ellipsoid_body(1.0, 0.3, 0.2, 0.1, 8);
  const gravitating_body<double> point{0.1, {}};
  const auto I = mat3<double>::identity();
  const vec3<double> r{2, 0, 0};
  BOOST_CHECK_THROW(mutual_gravity_at(four, I, eight, I, r, 1.0, 6), std::invalid_argument);
  BOOST_CHECK_THROW(mutual_gravity_at(eight, I, eight, I, r, 1.0, 9), std::invalid_argument);
  BOOST_CHECK_THROW(mutual_gravity_at(point, I, point, I, r, 1.0, max_gravity_order + 1), std::invalid_argument);
  BOOST_CHECK_THROW(mutual_gravity_at(point, I, point, I, r, 1.0, -1), std::invalid_argument);
  BOOST_CHECK_NO_THROW(mutual_gravity_at(eight, I, point, I, r, 1.0, 8));
  BOOST_CHECK_NO_THROW(mutual_gravity_at(point, I, point, I, r, 1.0, max_gravity_order));
}

BOOST_AUTO_TEST_SUITE_END()  // mutual_gravity_series_test
