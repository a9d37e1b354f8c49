#pragma once
// Whether a triangle mesh bounds a solid whose integrals the divergence theorem gives right. Summing
// the signed tetrahedra (polyhedron_body.hpp) integrates the winding number w(x) of the surface over
// space, so the integrals are the body's exactly when w is 1 inside and 0 outside. That holds when
//   1. the surface is closed and consistently oriented: every directed edge a→b is used by as many
//      facets as b→a (an edge of two cubes that share it has four facets, two each way);
//   2. no two facets meet except at the vertices and edges they share (no crossing, no touching, no
//      overlap), so w is constant off the surface and changes by one across a facet;
//   3. in front of each facet w = 0: checked once per piece of surface joined across edges of exactly
//      two facets (w in front is the same all over such a piece), by the facets' solid angles
//      (Van Oosterom & Strackee 1983) seen from its first facet's centroid. A shell nested in another
//      fails here (w = 1 in front), and so does a surface facing inward (w = −1).
// Pairs of facets are found through a uniform grid of cells about the size of a facet, so the check
// costs about as much as reading the file. Orientations are decided in double when the rounding bound
// allows, otherwise in __float128; what is still undecided counts as touching.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// A shape model: vertices (km) and triangular facets (0-based vertex indices, counter-clockwise from outside).
struct polyhedron {
  std::vector<vec3<double>> vertices;
  std::vector<std::array<int, 3>> facets;
};

namespace polyhedron_check_detail {

using point = vec3<double>;

inline point cross_product(const point& x, const point& y) { return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]}; }

/// The sign of det[b − a, c − a, d − a] (positive when d lies on the side of the plane abc that abc
/// turns counter-clockwise about): 0 when it cannot be told from zero.
inline int orientation(const point& a, const point& b, const point& c, const point& d) {
  const double ax = b[0] - a[0], ay = b[1] - a[1], az = b[2] - a[2];
  const double bx = c[0] - a[0], by = c[1] - a[1], bz = c[2] - a[2];
  const double cx = d[0] - a[0], cy = d[1] - a[1], cz = d[2] - a[2];
  const double det = ax * (by * cz - bz * cy) + bx * (cy * az - cz * ay) + cx * (ay * bz - az * by);
  const double permanent = std::abs(ax) * (std::abs(by * cz) + std::abs(bz * cy)) + std::abs(bx) * (std::abs(cy * az) + std::abs(cz * ay)) +
                           std::abs(cx) * (std::abs(ay * bz) + std::abs(az * by));
  // the differences round too: 16 units of round-off over the permanent bound everything
  const double bound = 16 * std::numeric_limits<double>::epsilon() * permanent;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (permanent == 0) return 0;
  using wide = __float128;  // the differences round at 2⁻¹¹³: 16 of those over the permanent bound the rest
  const auto d3 = [](const point& p, const point& q, std::size_t k) { return wide(q[k]) - wide(p[k]); };
  const wide X[3] = {d3(a, b, 0), d3(a, c, 0), d3(a, d, 0)}, Y[3] = {d3(a, b, 1), d3(a, c, 1), d3(a, d, 1)}, Z[3] = {d3(a, b, 2), d3(a, c, 2), d3(a, d, 2)};
  const wide wdet = X[0] * (Y[1] * Z[2] - Z[1] * Y[2]) + X[1] * (Y[2] * Z[0] - Z[2] * Y[0]) + X[2] * (Y[0] * Z[1] - Z[0] * Y[1]);
  const wide limit = wide(permanent) * wide(std::ldexp(1.0, -109));
  if (wdet > limit) return 1;
  if (wdet < -limit) return -1;
  return 0;
}

/// The plane a triangle is seen in: the two axes kept when the normal's largest component is dropped.
struct projection {
  int u = 0, v = 1;
};

inline projection projection_of(const point& a, const point& b, const point& c) {
  const point n = cross_product(point{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, point{c[0] - a[0], c[1] - a[1], c[2] - a[2]});
  const double x = std::abs(n[0]), y = std::abs(n[1]), z = std::abs(n[2]);
  if (x >= y && x >= z) return {1, 2};
  if (y >= z) return {2, 0};
  return {0, 1};
}

/// The sign of the turn a → b → c seen in the plane of `p`: 0 when it cannot be told from zero.
inline int turn(const projection& p, const point& a, const point& b, const point& c) {
  const auto U = static_cast<std::size_t>(p.u), V = static_cast<std::size_t>(p.v);
  const double bu = b[U] - a[U], bv = b[V] - a[V], cu = c[U] - a[U], cv = c[V] - a[V];
  const double det = bu * cv - bv * cu, bound = 8 * std::numeric_limits<double>::epsilon() * (std::abs(bu * cv) + std::abs(bv * cu));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  using wide = __float128;
  const wide wdet = (wide(b[U]) - wide(a[U])) * (wide(c[V]) - wide(a[V])) - (wide(b[V]) - wide(a[V])) * (wide(c[U]) - wide(a[U]));
  const wide limit = (wide(std::abs(bu * cv)) + wide(std::abs(bv * cu))) * wide(std::ldexp(1.0, -109));
  if (wdet > limit) return 1;
  if (wdet < -limit) return -1;
  return 0;
}

/// Whether q lies on the closed triangle abc, all four in the plane of `p`.
inline bool on_triangle(const projection& p, const point& q, const point& a, const point& b, const point& c) {
  const int s = turn(p, a, b, c), x = turn(p, a, b, q), y = turn(p, b, c, q), z = turn(p, c, a, q);
  return x * s >= 0 && y * s >= 0 && z * s >= 0;
}

/// Whether the closed segments ab and cd meet, all four in the plane of `p`.
inline bool segments_meet(const projection& p, const point& a, const point& b, const point& c, const point& d) {
  const int s1 = turn(p, a, b, c), s2 = turn(p, a, b, d), s3 = turn(p, c, d, a), s4 = turn(p, c, d, b);
  if (s1 * s2 < 0 && s3 * s4 < 0) return true;
  const auto within = [&](const point& x, const point& y, const point& q) {  // q on the line xy: between them?
    for (const int k : {p.u, p.v}) {
      const auto K = static_cast<std::size_t>(k);
      if (q[K] < std::min(x[K], y[K]) || q[K] > std::max(x[K], y[K])) return false;
    }
    return true;
  };
  return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) || (s3 == 0 && within(c, d, a)) || (s4 == 0 && within(c, d, b));
}

/// Whether the closed segment pq meets the closed triangle abc.
inline bool segment_meets_triangle(const point& p, const point& q, const point& a, const point& b, const point& c) {
  const int sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if (sp * sq > 0) return false;
  const auto plane = projection_of(a, b, c);
  if (sp == 0 && sq == 0)
    return on_triangle(plane, p, a, b, c) || on_triangle(plane, q, a, b, c) || segments_meet(plane, p, q, a, b) || segments_meet(plane, p, q, b, c) ||
           segments_meet(plane, p, q, c, a);
  if (sp == 0) return on_triangle(plane, p, a, b, c);
  if (sq == 0) return on_triangle(plane, q, a, b, c);
  // pq crosses the plane: the crossing lies on the triangle when pq passes each edge the same way
  const int x = orientation(p, q, a, b), y = orientation(p, q, b, c), z = orientation(p, q, c, a);
  return !((x > 0 || y > 0 || z > 0) && (x < 0 || y < 0 || z < 0));
}

/// Whether the closed triangles meet (they share no vertex).
inline bool triangles_meet(const std::array<point, 3>& s, const std::array<point, 3>& t) {
  const auto apart = [](const std::array<point, 3>& x, const std::array<point, 3>& y) {
    const int a = orientation(x[0], x[1], x[2], y[0]), b = orientation(x[0], x[1], x[2], y[1]), c = orientation(x[0], x[1], x[2], y[2]);
    return (a > 0 && b > 0 && c > 0) || (a < 0 && b < 0 && c < 0);
  };
  if (apart(s, t) || apart(t, s)) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (segment_meets_triangle(s[k], s[(k + 1) % 3], t[0], t[1], t[2]) || segment_meets_triangle(t[k], t[(k + 1) % 3], s[0], s[1], s[2])) return true;
  return false;
}

/// Whether the edge from v toward a runs into the triangle (v, c, d) beyond v: a in its plane, the
/// direction within the triangle's angle at v.
inline bool edge_enters(const point& v, const point& a, const point& c, const point& d) {
  if (orientation(v, c, d, a) != 0) return false;
  const auto plane = projection_of(v, c, d);
  const int s = turn(plane, v, c, d);
  return turn(plane, v, c, a) * s >= 0 && turn(plane, v, a, d) * s >= 0;
}

/// What the facets f and g have in common beyond their shared vertices: "" if nothing.
inline std::string facets_meet(const polyhedron& shape, const std::array<int, 3>& f, const std::array<int, 3>& g) {
  const auto at = [&](int i) -> const point& { return shape.vertices[static_cast<std::size_t>(i)]; };
  int shared = 0;
  std::array<int, 3> in_g{-1, -1, -1};  // the position in g of each of f's vertices
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (f[i] == g[k]) in_g[i] = static_cast<int>(k), ++shared;
  if (shared == 3) return "are the same triangle";
  if (shared == 2) {  // the shared edge uv; a and b opposite it
    std::size_t lone_f = 0, lone_g = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (in_g[i] < 0) lone_f = i;
    for (std::size_t k = 0; k < 3; ++k)
      if (std::find(f.begin(), f.end(), g[k]) == f.end()) lone_g = k;
    const point &u = at(f[(lone_f + 1) % 3]), &v = at(f[(lone_f + 2) % 3]), &a = at(f[lone_f]), &b = at(g[lone_g]);
    if (orientation(u, v, a, b) != 0) return "";
    const auto plane = projection_of(u, v, a);
    return turn(plane, u, v, a) * turn(plane, u, v, b) >= 0 ? "overlap, folded onto each other across their shared edge" : "";
  }
  if (shared == 1) {  // the shared vertex v; f = (v, a, b), g = (v, c, d)
    std::size_t i = 0, k = 0;
    while (in_g[i] < 0) ++i;
    k = static_cast<std::size_t>(in_g[i]);
    const point &v = at(f[i]), &a = at(f[(i + 1) % 3]), &b = at(f[(i + 2) % 3]), &c = at(g[(k + 1) % 3]), &d = at(g[(k + 2) % 3]);
    if (segment_meets_triangle(a, b, v, c, d) || segment_meets_triangle(c, d, v, a, b) || edge_enters(v, a, c, d) || edge_enters(v, b, c, d) ||
        edge_enters(v, c, a, b) || edge_enters(v, d, a, b))
      return "cross or touch beyond the vertex they share";
    return "";
  }
  if (!triangles_meet({at(f[0]), at(f[1]), at(f[2])}, {at(g[0]), at(g[1]), at(g[2])})) return "";
  for (const int i : f)
    for (const int k : g)
      if (at(i) == at(k))
        return "touch at vertices " + std::to_string(i + 1) + " and " + std::to_string(k + 1) +
               ", which are at the same place (facets may meet only at vertices they share: a vertex written twice is two vertices)";
  return "cross or touch";
}

/// The solid angle (signed, counter-clockwise from outside positive) the triangle abc subtends at p.
inline double solid_angle(const point& p, const point& a, const point& b, const point& c) {
  const point x{a[0] - p[0], a[1] - p[1], a[2] - p[2]}, y{b[0] - p[0], b[1] - p[1], b[2] - p[2]}, z{c[0] - p[0], c[1] - p[1], c[2] - p[2]};
  const double lx = norm(x), ly = norm(y), lz = norm(z);
  const double numerator = dot(x, cross_product(y, z));
  const double denominator = lx * ly * lz + dot(x, y) * lz + dot(x, z) * ly + dot(y, z) * lx;
  return 2 * std::atan2(numerator, denominator);
}

/// Disjoint sets over 0 … n−1.
struct partition {
  std::vector<std::size_t> up;
  explicit partition(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), std::size_t(0)); }
  std::size_t root(std::size_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  }
  void join(std::size_t x, std::size_t y) { up[root(x)] = root(y); }
};

struct box {
  point lo, hi;
};

inline box box_of(const polyhedron& shape, const std::array<int, 3>& t) {
  box b{shape.vertices[static_cast<std::size_t>(t[0])], shape.vertices[static_cast<std::size_t>(t[0])]};
  for (std::size_t k = 1; k < 3; ++k)
    for (std::size_t i = 0; i < 3; ++i) {
      const double x = shape.vertices[static_cast<std::size_t>(t[k])][i];
      b.lo[i] = std::min(b.lo[i], x), b.hi[i] = std::max(b.hi[i], x);
    }
  return b;
}

inline std::string facet_name(std::size_t f) { return "facet " + std::to_string(f + 1); }

/// Throws unless no two facets meet beyond the vertices they share (condition 2).
inline void check_no_intersection(const polyhedron& shape) {
  const std::size_t n = shape.facets.size();
  std::vector<box> boxes(n);
  box all{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  double mean_size = 0;
  for (std::size_t f = 0; f < n; ++f) {
    boxes[f] = box_of(shape, shape.facets[f]);
    for (std::size_t i = 0; i < 3; ++i) all.lo[i] = std::min(all.lo[i], boxes[f].lo[i]), all.hi[i] = std::max(all.hi[i], boxes[f].hi[i]);
    mean_size += std::max({boxes[f].hi[0] - boxes[f].lo[0], boxes[f].hi[1] - boxes[f].lo[1], boxes[f].hi[2] - boxes[f].lo[2]}) / static_cast<double>(n);
  }
  // cells of about a facet's size, coarser if the facets' boxes would take more than 16 cells each on average
  const double extent = std::max({all.hi[0] - all.lo[0], all.hi[1] - all.lo[1], all.hi[2] - all.lo[2]});
  double cell = std::max(mean_size, extent * std::ldexp(1.0, -20));
  const auto cell_of = [&](double x, std::size_t i) { return static_cast<std::int64_t>(std::floor((x - all.lo[i]) / cell)); };
  const auto cells_of = [&](const box& b) {
    double k = 1;
    for (std::size_t i = 0; i < 3; ++i) k *= static_cast<double>(cell_of(b.hi[i], i) - cell_of(b.lo[i], i) + 1);
    return k;
  };
  for (;;) {
    double total = 0;
    for (const auto& b : boxes) total += cells_of(b);
    if (total <= 16.0 * static_cast<double>(n) + 64) break;
    cell *= 2;
  }
  const auto cell_id = [&](std::int64_t x, std::int64_t y, std::int64_t z) { return (x << 42) | (y << 21) | z; };  // each below 2²¹
  std::vector<std::pair<std::int64_t, std::uint32_t>> entries;
  entries.reserve(2 * n);
  for (std::size_t f = 0; f < n; ++f) {
    const auto& b = boxes[f];
    for (auto x = cell_of(b.lo[0], 0); x <= cell_of(b.hi[0], 0); ++x)
      for (auto y = cell_of(b.lo[1], 1); y <= cell_of(b.hi[1], 1); ++y)
        for (auto z = cell_of(b.lo[2], 2); z <= cell_of(b.hi[2], 2); ++z) entries.emplace_back(cell_id(x, y, z), static_cast<std::uint32_t>(f));
  }
  std::sort(entries.begin(), entries.end());
  for (std::size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    end = begin + 1;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t k = i + 1; k < end; ++k) {
        const std::size_t f = entries[i].second, g = entries[k].second;
        const auto &bf = boxes[f], &bg = boxes[g];
        if (bf.lo[0] > bg.hi[0] || bg.lo[0] > bf.hi[0] || bf.lo[1] > bg.hi[1] || bg.lo[1] > bf.hi[1] || bf.lo[2] > bg.hi[2] || bg.lo[2] > bf.hi[2]) continue;
        // each pair once: in the cell holding the low corner of the boxes' overlap
        if (cell_id(cell_of(std::max(bf.lo[0], bg.lo[0]), 0), cell_of(std::max(bf.lo[1], bg.lo[1]), 1), cell_of(std::max(bf.lo[2], bg.lo[2]), 2)) !=
            entries[begin].first)
          continue;
        const auto why = facets_meet(shape, shape.facets[f], shape.facets[g]);
        if (!why.empty())
          throw std::invalid_argument("polyhedron: the surface meets itself: facets " + std::to_string(std::min(f, g) + 1) + " and " +
                                      std::to_string(std::max(f, g) + 1) + " " + why);
      }
  }
}

/// Throws unless the winding number is 0 in front of every facet (condition 3).
inline void check_winding(const polyhedron& shape) {
  const std::size_t n = shape.facets.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> around;  // (undirected edge, facet), sorted: the facets at each edge
  around.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [a, b] = std::minmax(shape.facets[f][k], shape.facets[f][(k + 1) % 3]);
      around.emplace_back(std::uint64_t(std::uint32_t(a)) << 32 | std::uint32_t(b), static_cast<std::uint32_t>(f));
    }
  std::sort(around.begin(), around.end());
  partition piece(n), closed(n);  // joined across edges of two facets; across every edge
  for (std::size_t begin = 0, end = 0; begin < around.size(); begin = end) {
    end = begin + 1;
    while (end < around.size() && around[end].first == around[begin].first) ++end;
    for (std::size_t k = begin + 1; k < end; ++k) closed.join(around[begin].second, around[k].second);
    if (end - begin == 2) piece.join(around[begin].second, around[begin + 1].second);
  }
  // the closed parts and their boxes: a closed surface winds 0 times about a point outside its box
  std::vector<std::vector<std::uint32_t>> members(n);
  for (std::size_t f = 0; f < n; ++f) members[closed.root(f)].push_back(static_cast<std::uint32_t>(f));
  std::vector<std::size_t> parts;
  std::vector<box> part_box;
  for (std::size_t r = 0; r < n; ++r) {
    if (members[r].empty()) continue;
    parts.push_back(r);
    box b = box_of(shape, shape.facets[members[r][0]]);
    for (const auto f : members[r]) {
      const auto c = box_of(shape, shape.facets[f]);
      for (std::size_t i = 0; i < 3; ++i) b.lo[i] = std::min(b.lo[i], c.lo[i]), b.hi[i] = std::max(b.hi[i], c.hi[i]);
    }
    part_box.push_back(b);
  }
  std::vector<bool> seen(n, false);
  double work = 0;  // solid angles and boxes looked at
  for (std::size_t f = 0; f < n; ++f) {
    const auto r = piece.root(f);
    if (seen[r]) continue;
    seen[r] = true;
    const auto& t = shape.facets[f];
    const auto &a = shape.vertices[static_cast<std::size_t>(t[0])], &b = shape.vertices[static_cast<std::size_t>(t[1])],
               &c = shape.vertices[static_cast<std::size_t>(t[2])];
    const point p{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
    double total = 0;
    for (std::size_t m = 0; m < parts.size(); ++m) {
      const auto& B = part_box[m];
      work += 0.05;
      // (f's own part always: the centroid may round to just outside its box)
      if (parts[m] != closed.root(f) && (p[0] < B.lo[0] || p[0] > B.hi[0] || p[1] < B.lo[1] || p[1] > B.hi[1] || p[2] < B.lo[2] || p[2] > B.hi[2])) continue;
      work += static_cast<double>(members[parts[m]].size());
      if (work > 1e8)
        throw std::invalid_argument("polyhedron: too many separate pieces of surface to check that they bound one solid (" + std::to_string(n) +
                                    " facets)");
      for (const auto g : members[parts[m]]) {
        if (g == f) continue;
        const auto& s = shape.facets[g];
        total += solid_angle(p, shape.vertices[static_cast<std::size_t>(s[0])], shape.vertices[static_cast<std::size_t>(s[1])],
                             shape.vertices[static_cast<std::size_t>(s[2])]);
      }
    }
    // just in front of f its own solid angle is −2π: w = (total − 2π)/4π there, w + 1 behind
    const double w = (total - 2 * std::numbers::pi) / (4 * std::numbers::pi);
    const double k = std::round(w);
    if (std::abs(w - k) > 0.25 || k != 0) {
      if (k == -1 && std::abs(w - k) <= 0.25) throw std::invalid_argument("polyhedron: the facets face inward (" + facet_name(f) + " and those joined to it)");
      throw std::invalid_argument("polyhedron: " + facet_name(f) + " and those joined to it lie inside the solid (a shell nested in another, " +
                                  "or one facing the wrong way): the surface winds " + std::to_string(static_cast<long>(k) + 1) + " times about the points behind it");
    }
  }
}

}  // namespace polyhedron_check_detail

/// Throws std::invalid_argument unless the surface bounds a solid (see the top of this file): every
/// index valid, no facet with a repeated vertex or without area, every directed edge used as often
/// as its reverse, no two facets meeting beyond their shared vertices and edges, the winding number
/// 0 in front of every facet. Edges of more than two facets (two cubes sharing an edge) are allowed.
inline void check_polyhedron(const polyhedron& shape) {
  using namespace polyhedron_check_detail;
  if (shape.vertices.size() < 4 || shape.facets.size() < 4)
    throw std::invalid_argument("polyhedron: " + std::to_string(shape.vertices.size()) + " vertices and " + std::to_string(shape.facets.size()) +
                                " facets (a closed solid needs at least 4 of each)");
  if (shape.facets.size() > std::size_t(UINT32_MAX)) throw std::invalid_argument("polyhedron: more than 2³² facets");
  for (const auto& v : shape.vertices)
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) throw std::invalid_argument("polyhedron: a vertex is not finite");
  const int n = static_cast<int>(shape.vertices.size());
  std::vector<std::uint64_t> edges;  // directed, a → b as a·2³² + b
  edges.reserve(3 * shape.facets.size());
  for (std::size_t f = 0; f < shape.facets.size(); ++f) {
    const auto& t = shape.facets[f];
    for (int k = 0; k < 3; ++k)
      if (t[static_cast<std::size_t>(k)] < 0 || t[static_cast<std::size_t>(k)] >= n)
        throw std::invalid_argument("polyhedron: " + facet_name(f) + " names vertex " + std::to_string(t[static_cast<std::size_t>(k)] + 1) + " of " +
                                    std::to_string(n));
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) throw std::invalid_argument("polyhedron: " + facet_name(f) + " repeats a vertex");
    const auto &a = shape.vertices[static_cast<std::size_t>(t[0])], &b = shape.vertices[static_cast<std::size_t>(t[1])],
               &c = shape.vertices[static_cast<std::size_t>(t[2])];
    if (turn(projection_of(a, b, c), a, b, c) == 0) throw std::invalid_argument("polyhedron: " + facet_name(f) + " has no area (its vertices lie on one line)");
    for (std::size_t k = 0; k < 3; ++k) edges.push_back(std::uint64_t(std::uint32_t(t[k])) << 32 | std::uint32_t(t[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t begin = 0, end = 0; begin < edges.size(); begin = end) {
    end = begin + 1;
    while (end < edges.size() && edges[end] == edges[begin]) ++end;
    const std::uint64_t reverse = (edges[begin] << 32) | (edges[begin] >> 32);
    const auto [lo, hi] = std::equal_range(edges.begin(), edges.end(), reverse);
    if (hi - lo != static_cast<std::ptrdiff_t>(end - begin))
      throw std::invalid_argument("polyhedron: not a closed, consistently oriented surface (edge " + std::to_string((edges[begin] >> 32) + 1) + "–" +
                                  std::to_string((edges[begin] & 0xffffffffu) + 1) + " is used " + std::to_string(end - begin) + " times one way and " +
                                  std::to_string(hi - lo) + " the other)");
  }
  check_no_intersection(shape);
  check_winding(shape);
}

}  // namespace rotlie::models
