// Which meshes bound a solid (polyhedron_check.hpp): two cubes sharing an edge (four facets at it) are
// one solid with the closed-form volume, centroid and inertia, and integrals the sum of the cubes';
// a hollow box is a solid; a surface that crosses itself, touches itself, folds onto itself, repeats
// a facet, holds a facet without area, nests a shell in another or faces inward is refused in one
// line; and a mesh of 32,768 facets is checked in well under a second.
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "rotlie/models/scenes/polyhedron_body.hpp"

BOOST_AUTO_TEST_SUITE(polyhedron_check_test)

using namespace rotlie::models;
using ld = long double;

namespace {

// The box [x, x + a] × [y, y + b] × [z, z + c], counter-clockwise from outside.
polyhedron box(double x, double y, double z, double a, double b, double c) {
  polyhedron p;
  for (int i = 0; i < 8; ++i) p.vertices.push_back({x + (i & 1 ? a : 0), y + (i & 2 ? b : 0), z + (i & 4 ? c : 0)});
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    p.facets.push_back({f[0], f[1], f[2]});
    p.facets.push_back({f[0], f[2], f[3]});
  }
  return p;
}

// Both meshes in one, each vertex of the second that the first has at the same place merged into it
// when `merge` (otherwise written twice).
polyhedron together(polyhedron a, const polyhedron& b, bool merge) {
  std::vector<int> index;
  for (const auto& v : b.vertices) {
    int k = -1;
    for (std::size_t i = 0; merge && i < a.vertices.size(); ++i)
      if (a.vertices[i] == v) k = static_cast<int>(i);
    if (k < 0) {
      a.vertices.push_back(v);
      k = static_cast<int>(a.vertices.size()) - 1;
    }
    index.push_back(k);
  }
  for (const auto& f : b.facets)
    a.facets.push_back({index[static_cast<std::size_t>(f[0])], index[static_cast<std::size_t>(f[1])], index[static_cast<std::size_t>(f[2])]});
  return a;
}

polyhedron turned_inside_out(polyhedron p) {
  for (auto& f : p.facets) std::swap(f[1], f[2]);
  return p;
}

// The unit sphere as an octahedron subdivided `level` times, stretched along the axes.
polyhedron ellipsoid_mesh(int level, double a, double b, double c) {
  polyhedron p;
  p.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  p.facets = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      if (const auto found = middle.find(key); found != middle.end()) return found->second;
      const auto &x = p.vertices[static_cast<std::size_t>(i)], &y = p.vertices[static_cast<std::size_t>(j)];
      const vec3<double> m{x[0] + y[0], x[1] + y[1], x[2] + y[2]};
      const double n = std::sqrt(dot(m, m));
      p.vertices.push_back({m[0] / n, m[1] / n, m[2] / n});
      return middle[key] = static_cast<int>(p.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : p.facets) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca}), finer.push_back({ab, t[1], bc}), finer.push_back({ca, bc, t[2]}), finer.push_back({ab, bc, ca});
    }
    p.facets = finer;
  }
  for (auto& v : p.vertices) v = {a * v[0], b * v[1], c * v[2]};
  return p;
}

// The message check_polyhedron refuses the mesh with, or "" if it accepts it.
std::string refusal(const polyhedron& p) {
  try {
    check_polyhedron(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// Unit cubes [0,1]³ and [1,2]×[1,2]×[0,1] share the edge x = y = 1. Volume 2, centroid (1, 1, ½); about
// it each cube has I = 1/6 + (|d|² − d dᵀ) with d = ±(½, ½, 0), so the principal moments are 1/3 along
// (1, 1, 0)/√2 and 4/3 across; the solid is symmetric through its centroid (the third degree vanishes).
BOOST_AUTO_TEST_CASE(two_cubes_sharing_an_edge_are_one_solid) {
  const auto first = box(0, 0, 0, 1, 1, 1), second = box(1, 1, 0, 1, 1, 1);
  const auto both = together(first, second, true);
  BOOST_TEST_REQUIRE(both.vertices.size() == 14u);  // two vertices shared: the edge has four facets
  BOOST_TEST(refusal(both) == "");
  const auto p = polyhedron_body<ld>(both, 1.0L);
  BOOST_TEST(std::abs(p.volume - 2) <= 1e-17L);
  const ld centroid[3] = {1, 1, 0.5L};
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(p.centroid[k] - centroid[k]) <= 1e-17L, "centroid " << k);
  const ld moments[3] = {1.0L / 3, 4.0L / 3, 4.0L / 3};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) BOOST_TEST(std::abs(p.body.inertia(i, j) - (i == j ? moments[i] : 0.0L)) <= 1e-17L, "I(" << i << "," << j << ")");
  const ld along = std::abs(p.axes(0, 0) + p.axes(1, 0)) / std::sqrt(2.0L);  // the least moment's axis is (1, 1, 0)/√2
  BOOST_TEST(std::abs(along - 1) <= 1e-17L);
  for (const auto x : p.body.third) BOOST_TEST(std::abs(x) <= 1e-17L);
  // every degree is the sum of the two cubes' (the divergence theorem sees the shared edge as any other)
  const auto whole = polyhedron_detail::integrate<ld>(both, p.centroid, p.axes);
  const auto a = polyhedron_detail::integrate<ld>(first, p.centroid, p.axes), b = polyhedron_detail::integrate<ld>(second, p.centroid, p.axes);
  [&]<std::size_t... K>(std::index_sequence<K...>) {
    (
        [&] {
          for (std::size_t i = 0; i < std::get<K>(whole).size(); ++i)
            BOOST_TEST(std::abs(std::get<K>(whole)[i] - std::get<K>(a)[i] - std::get<K>(b)[i]) <= 1e-17L, "degree " << K << ", component " << i);
        }(),
        ...);
  }(std::make_index_sequence<5>{});
}

BOOST_AUTO_TEST_CASE(a_hollow_box_is_a_solid) {
  const auto hollow = together(box(0, 0, 0, 3, 3, 3), turned_inside_out(box(1, 1, 1, 1, 1, 1)), false);
  BOOST_TEST(refusal(hollow) == "");
  BOOST_TEST(std::abs(polyhedron_body<ld>(hollow, 1.0L).volume - 26) <= 1e-16L);
}

BOOST_AUTO_TEST_CASE(meshes_that_are_not_solids_are_refused_in_one_line) {
  auto crossing = ellipsoid_mesh(3, 0.4, 0.38, 0.35);
  crossing.vertices[0] = {-0.6, 0, 0};  // a vertex pushed through the far side
  auto repeated = together(box(0, 0, 0, 1, 1, 1), {}, true);
  repeated.facets.push_back(repeated.facets[0]);
  repeated.facets.push_back({repeated.facets[0][0], repeated.facets[0][2], repeated.facets[0][1]});
  auto flat = box(0, 0, 0, 1, 1, 1);
  flat.vertices.push_back({1, 1, 0.5});  // the midpoint of the edge from vertex 4 (1,1,0) to 8 (1,1,1)
  flat.facets.push_back({3, 8, 7});
  flat.facets.push_back({3, 7, 8});
  // a tetrahedron inside a box on an edge of it: four facets at that edge, all edges balanced, nothing
  // crossing, but the tetrahedron's inside is counted twice
  auto wedged = box(0, 0, 0, 2, 2, 1);
  wedged.vertices.push_back({1, 0.5, 0.5});
  wedged.vertices.push_back({0.5, 1, 0.5});
  for (const auto& f : {std::array<int, 3>{0, 8, 4}, {0, 4, 9}, {0, 9, 8}, {4, 8, 9}}) wedged.facets.push_back(f);
  const std::pair<polyhedron, std::string> cases[] = {
      {wedged, "lie inside the solid (a shell nested in another"},
      {crossing, "the surface meets itself: facets"},
      {together(box(0, 0, 0, 1, 1, 1), box(0.5, 0.5, 0.5, 1, 1, 1), false), "the surface meets itself: facets"},
      {together(box(0, 0, 0, 1, 1, 1), box(1, 1, 0, 1, 1, 1), false), "a vertex written twice is two vertices"},
      {together(box(0, 0, 0, 1, 1, 1), box(0.25, 0.25, 0.25, 0.5, 0.5, 0.5), false), "lie inside the solid (a shell nested in another"},
      {turned_inside_out(box(0, 0, 0, 1, 1, 1)), "the facets face inward"},
      {repeated, "are the same triangle"},
      {flat, "has no area"},
  };
  for (const auto& [mesh, words] : cases) {
    const auto why = refusal(mesh);
    BOOST_TEST(why.find(words) != std::string::npos, "'" << why << "' should say '" << words << "'");
    BOOST_TEST(why.find('\n') == std::string::npos, why);
  }
  // a facet folded onto its neighbour across their shared edge: the box's side x = 1 is the facets
  // (1, 3, 7) and (1, 7, 5); the first replaced by (1, 3, 8), (3, 7, 8), (7, 1, 8) about a point in
  // that side, and the last of those turned over onto (1, 7, 5)'s half
  auto fold = box(0, 0, 0, 1, 1, 1);
  fold.vertices.push_back({1, 0.6, 0.3});
  BOOST_TEST_REQUIRE(fold.facets[10] == (std::array<int, 3>{1, 3, 7}));
  fold.facets[10] = {1, 3, 8};
  fold.facets.push_back({3, 7, 8});
  fold.facets.push_back({7, 1, 8});
  BOOST_TEST(refusal(fold) == "");  // the side split in three: still a box
  fold.vertices[8] = {1, 0.3, 0.6};  // now inside the other half of the side: (7, 1, 8) lies on (1, 7, 5)
  BOOST_TEST(refusal(fold).find("the surface meets itself") != std::string::npos, refusal(fold));
}

// The check finds pairs through a grid, so its cost grows with the facets, not their square.
BOOST_AUTO_TEST_CASE(a_fine_mesh_is_checked_quickly) {
  const auto mesh = ellipsoid_mesh(6, 0.4, 0.38, 0.35);
  const auto start = std::chrono::steady_clock::now();
  BOOST_TEST(refusal(mesh) == "");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST_MESSAGE(mesh.facets.size() << " facets checked in " << seconds << " s");
  BOOST_TEST(seconds < 10);  // about 0.1 s optimised; the bound leaves room for sanitizers and a loaded machine
}

BOOST_AUTO_TEST_SUITE_END()  // polyhedron_check_test
