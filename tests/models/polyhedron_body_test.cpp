// A homogeneous polyhedron's inertia integrals (polyhedron_body.hpp) against closed forms: the corner
// tetrahedron's moments by Dirichlet's integral, a box turned and moved anywhere, and an ellipsoid's
// integrals approached at second order in the edge as its mesh refines; bad meshes refused.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>

#include "rotlie/models/scenes/polyhedron_body.hpp"

BOOST_AUTO_TEST_SUITE(polyhedron_body_test)

using namespace rotlie::models;
using ld = long double;

namespace {

polyhedron box(double a, double b, double c) {
  polyhedron p;
  for (int i = 0; i < 8; ++i) p.vertices.push_back({i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c});
  // two counter-clockwise triangles per face, seen from outside
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    p.facets.push_back({f[0], f[1], f[2]});
    p.facets.push_back({f[0], f[2], f[3]});
  }
  return p;
}

// The unit sphere as an octahedron subdivided `level` times (each triangle into four, the new vertices
// pushed to the sphere), stretched along the axes.
polyhedron ellipsoid_mesh(int level, double a, double b, double c) {
  polyhedron p;
  p.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  p.facets = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      const auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      const auto &x = p.vertices[static_cast<std::size_t>(i)], &y = p.vertices[static_cast<std::size_t>(j)];
      vec3<double> m{x[0] + y[0], x[1] + y[1], x[2] + y[2]};
      const double n = std::sqrt(dot(m, m));
      p.vertices.push_back({m[0] / n, m[1] / n, m[2] / n});
      return middle[key] = static_cast<int>(p.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : p.facets) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    p.facets = finer;
  }
  for (auto& v : p.vertices) v = {a * v[0], b * v[1], c * v[2]};
  return p;
}

ld largest_difference(const auto& x, const auto& y) {
  ld d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) d = std::max(d, std::abs(x[i] - y[i]));
  return d;
}

ld largest(const auto& x) {
  ld d = 0;
  for (const auto v : x) d = std::max(d, std::abs(v));
  return d;
}

}  // namespace

// ∫ x^p y^q z^s over {x/a + y/b + z/c ≤ 1, x, y, z ≥ 0} = a^(p+1) b^(q+1) c^(s+1) p! q! s! / (p+q+s+3)!.
BOOST_AUTO_TEST_CASE(the_corner_tetrahedron_has_dirichlets_moments) {
  const double a = 1.3, b = 0.7, c = 0.4;
  polyhedron tetra;
  tetra.vertices = {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}};
  tetra.facets = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto raw = polyhedron_detail::integrate<ld>(tetra, vec3<ld>{}, mat3<ld>::identity());
  const auto dirichlet = [&](int p, int q, int s) {
    const ld f[8] = {1, 1, 2, 6, 24, 120, 720, 5040};
    return std::pow(ld(a), p + 1) * std::pow(ld(b), q + 1) * std::pow(ld(c), s + 1) * f[p] * f[q] * f[s] / f[p + q + s + 3];
  };
  BOOST_TEST(std::abs(std::get<0>(raw)[0] - dirichlet(0, 0, 0)) <= 1e-18L);  // the degrees 0 … 4 at std::get<0 … 4>
  BOOST_TEST(std::abs(std::get<1>(raw)[1] - dirichlet(0, 1, 0)) <= 1e-18L);
  const auto check = [&](const auto& tensor, int K) {
    for (std::size_t index = 0; index < tensor.size(); ++index) {
      int count[3] = {0, 0, 0};
      for (std::size_t rest = index, slot = 0; slot < static_cast<std::size_t>(K); ++slot, rest /= 3) ++count[rest % 3];
      const ld expected = dirichlet(count[0], count[1], count[2]);
      BOOST_TEST(std::abs(tensor[index] - expected) <= 1e-17L * expected, "degree " << K << ", component " << index);
    }
  };
  check(std::get<2>(raw), 2), check(std::get<3>(raw), 3), check(std::get<4>(raw), 4);
}

// A box of half-sides a > b > c: J = M diag(a², b², c²)/3, ∫x⁴ dm = M a⁴/5, ∫x²y² dm = M a²b²/9, the odd
// ones zero; the same wherever it is placed and however it is turned, its principal axes found.
BOOST_AUTO_TEST_CASE(a_box_anywhere_has_the_box_integrals_and_its_axes) {
  const double a = 0.9, b = 0.5, c = 0.3, density = 2.0;
  const auto R = rotation<double>({0.36, 0.48, 0.8}, 0.9);
  auto shape = box(a, b, c);
  for (auto& v : shape.vertices) {
    const auto w = R * v;
    v = {w[0] + 3.1, w[1] - 1.7, w[2] + 0.4};
  }
  const auto p = polyhedron_body<ld>(shape, ld(density));
  const ld M = density * 8 * a * b * c;
  BOOST_TEST(std::abs(p.body.mass - M) <= 1e-15L * M);
  BOOST_TEST(std::abs(p.centroid[0] - 3.1L) <= 1e-15L);
  const ld expected_inertia[3] = {M * (b * b + c * c) / 3, M * (a * a + c * c) / 3, M * (a * a + b * b) / 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      BOOST_TEST(std::abs(p.body.inertia(i, j) - (i == j ? expected_inertia[i] : 0.0L)) <= 1e-14L * M, "I(" << i << "," << j << ")");
  for (int k = 0; k < 3; ++k) {
    // each principal axis is the box's, up to its sign
    const ld along = std::abs(p.axes(0, k) * R(0, k) + p.axes(1, k) * R(1, k) + p.axes(2, k) * R(2, k));
    BOOST_TEST(std::abs(along - 1) <= 1e-14L, "axis " << k);
  }
  BOOST_TEST(largest(p.body.third) <= 1e-14L * M);
  const ld half[3] = {a, b, c};
  for (std::size_t index = 0; index < p.body.fourth.size(); ++index) {
    int count[3] = {0, 0, 0};
    for (std::size_t rest = index, slot = 0; slot < 4; ++slot, rest /= 3) ++count[rest % 3];
    ld expected = 0;
    if (!(count[0] % 2 || count[1] % 2 || count[2] % 2)) {
      expected = M;
      for (int k = 0; k < 3; ++k) expected *= std::pow(ld(half[k]), count[k]) / (count[k] == 4 ? 5 : count[k] == 2 ? 3 : 1);
    }
    BOOST_TEST(std::abs(p.body.fourth[index] - expected) <= 1e-14L * M, "component " << index);
  }
}

// The mesh inscribed in an ellipsoid converges to its integrals at the same density: the gap is the
// shell between the facets and the surface, of thickness ∝ edge², so each refinement (edges halved)
// divides every integral's error by about 4.
BOOST_AUTO_TEST_CASE(an_ellipsoids_mesh_converges_to_its_integrals) {
  const double a = 0.42, b = 0.40, c = 0.37, density = 3.0;
  const ld pi = std::acos(-1.0L), M = density * 4 * pi * a * b * c / 3;
  const auto exact = ellipsoid_body<ld>(M, a, b, c);
  ld previous[3] = {0, 0, 0};
  for (int level = 2; level <= 5; ++level) {
    const auto p = polyhedron_body<ld>(ellipsoid_mesh(level, a, b, c), ld(density));
    const ld errors[3] = {std::abs(p.body.mass - M) / M, largest_difference(p.body.inertia.a, exact.inertia.a) / largest(exact.inertia.a),
                          largest_difference(p.body.fourth, exact.fourth) / largest(exact.fourth)};
    BOOST_TEST_MESSAGE("level " << level << " (" << 8 * (1 << (2 * level)) << " facets): relative errors of the mass " << static_cast<double>(errors[0])
                                << ", the inertia " << static_cast<double>(errors[1]) << ", the fourth degree " << static_cast<double>(errors[2]));
    if (level > 2)
      for (int k = 0; k < 3; ++k) {
        const ld ratio = previous[k] / errors[k];
        BOOST_TEST((ratio > 3.5L && ratio < 4.5L), "level " << level << ", integral " << k << ": ratio " << static_cast<double>(ratio));
      }
    for (int k = 0; k < 3; ++k) previous[k] = errors[k];
    BOOST_TEST(largest(p.body.third) <= 1e-15L * M);  // the mesh is as symmetric as the ellipsoid
  }
}

// To degree 10 by the monomial series (polyhedron_moments.hpp): the corner tetrahedron's Dirichlet
// moments, a box anywhere (its moments M Π half^p/(p+1) for even p, zero for odd), degrees ≤ 4 as the
// tensors, and an ellipsoid's mesh converging to the closed form at second order at degrees 6 and 8.
BOOST_AUTO_TEST_CASE(the_moments_of_any_degree_are_exact) {
  const double a = 1.3, b = 0.7, c = 0.4;
  polyhedron tetra;
  tetra.vertices = {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}};
  tetra.facets = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto& table = monomial_table::get();
  const auto factorial = [](int n) {
    ld f = 1;
    for (int q = 2; q <= n; ++q) f *= q;
    return f;
  };
  const auto moments = polyhedron_monomial_moments<ld>(tetra, vec3<ld>{}, mat3<ld>::identity(), 10);
  for (std::size_t i = 0; i < moments.size(); ++i) {
    const auto& e = table.exponents[i];
    const ld expected = std::pow(ld(a), e[0] + 1) * std::pow(ld(b), e[1] + 1) * std::pow(ld(c), e[2] + 1) * factorial(e[0]) * factorial(e[1]) *
                        factorial(e[2]) / factorial(e[0] + e[1] + e[2] + 3);
    BOOST_TEST(std::abs(moments[i] - expected) <= 1e-17L * expected, "monomial " << i);
  }
  // a box turned and moved: in its principal frame, the box's moments
  const double half[3] = {0.9, 0.5, 0.3}, density = 2.0;
  const auto R = rotation<double>({0.36, 0.48, 0.8}, 0.9);
  auto shape = box(half[0], half[1], half[2]);
  for (auto& v : shape.vertices) {
    const auto w = R * v;
    v = {w[0] + 3.1, w[1] - 1.7, w[2] + 0.4};
  }
  const auto p = polyhedron_body<ld>(shape, ld(density), 10);
  BOOST_TEST(p.body.degree == 10);
  const ld M = density * 8 * half[0] * half[1] * half[2];
  for (std::size_t i = 0; i < p.body.moments.size(); ++i) {
    const auto& e = table.exponents[i];
    ld expected = 0;
    if (!(e[0] % 2 || e[1] % 2 || e[2] % 2)) {
      expected = M;
      for (std::size_t k = 0; k < 3; ++k) expected *= std::pow(ld(half[k]), e[k]) / (e[k] + 1);
    }
    BOOST_TEST(std::abs(p.body.moments[i] - expected) <= 1e-14L * M, "monomial " << i);
  }
  std::vector<ld> from_tensors(static_cast<std::size_t>(monomials_up_to(4)));
  gravitating_body<ld> tensors_only = p.body;
  tensors_only.moments.clear();
  body_moments(tensors_only, 4, from_tensors.data());
  for (std::size_t i = 0; i < from_tensors.size(); ++i) BOOST_TEST(std::abs(from_tensors[i] - p.body.moments[i]) <= 1e-15L * M, "monomial " << i);
  // an ellipsoid's mesh: the largest relative error at degrees 6 and 8 divided by about 4 per refinement
  const double sa = 0.42, sb = 0.40, sc = 0.37;
  const ld pi = std::acos(-1.0L), mass = 3.0L * 4 * pi * sa * sb * sc / 3;
  const auto exact = ellipsoid_moments<ld>(mass, sa, sb, sc, 8);
  ld previous = 0;
  for (int level = 3; level <= 5; ++level) {
    const auto mesh = polyhedron_body<double>(ellipsoid_mesh(level, sa, sb, sc), 3.0, 8);  // errors of 1e-2: double suffices
    ld error = 0, size = 0;
    for (int i = first_monomial(6); i < monomials_up_to(8); ++i) {
      if (first_monomial(7) <= i && i < first_monomial(8)) continue;  // the odd degree vanishes in both
      error = std::max(error, std::abs(mesh.body.moments[static_cast<std::size_t>(i)] - exact[static_cast<std::size_t>(i)]));
      size = std::max(size, std::abs(exact[static_cast<std::size_t>(i)]));
    }
    BOOST_TEST_MESSAGE("level " << level << ": largest relative error of the degree 6 and 8 moments " << static_cast<double>(error / size));
    if (level > 3) BOOST_TEST((previous / error > 3.5L && previous / error < 4.5L), "level " << level << ": ratio " << static_cast<double>(previous / error));
    previous = error;
  }
}

BOOST_AUTO_TEST_CASE(bad_meshes_are_refused) {
  const auto good = box(0.3, 0.2, 0.1);
  BOOST_CHECK_NO_THROW(polyhedron_body<double>(good, 1.0));
  auto open = good;
  open.facets.pop_back();
  BOOST_CHECK_THROW(polyhedron_body<double>(open, 1.0), std::invalid_argument);
  auto inverted = good;
  for (auto& f : inverted.facets) std::swap(f[1], f[2]);
  BOOST_CHECK_THROW(polyhedron_body<double>(inverted, 1.0), std::invalid_argument);
  auto flipped_one = good;
  std::swap(flipped_one.facets[3][1], flipped_one.facets[3][2]);
  BOOST_CHECK_THROW(polyhedron_body<double>(flipped_one, 1.0), std::invalid_argument);
  auto out_of_range = good;
  out_of_range.facets[0][2] = 8;
  BOOST_CHECK_THROW(polyhedron_body<double>(out_of_range, 1.0), std::invalid_argument);
  auto repeated = good;
  repeated.facets[0][2] = repeated.facets[0][1];
  BOOST_CHECK_THROW(polyhedron_body<double>(repeated, 1.0), std::invalid_argument);
  auto not_finite = good;
  not_finite.vertices[0][0] = std::nan("");
  BOOST_CHECK_THROW(polyhedron_body<double>(not_finite, 1.0), std::invalid_argument);
  BOOST_CHECK_THROW(polyhedron_body<double>(good, 0.0), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // polyhedron_body_test
