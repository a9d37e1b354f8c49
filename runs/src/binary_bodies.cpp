#include "rotlie/runs/binary_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <map>
#include <sstream>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/monomial_moments.hpp"
#include "rotlie/models/scenes/polyhedron_moments.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "shape_formats/gubas_shape.hpp"
#include "shape_formats/icq_shape.hpp"
#include "shape_formats/vertex_text.hpp"

namespace rotlie::runs {

namespace {

using models::norm;
using models::vec3;

constexpr std::size_t shape_file_limit = std::size_t(256) << 20;  // 256 MiB: millions of facets
constexpr double m3_per_km3 = 1e9;  // a density in kg/m³ times this is kg/km³
// The range of a shape model's size (km): its coordinates at most 1e20 in size (vertex_text.hpp), and
// its extent at least this: the integrals to degree 4 (size⁷ times the density) and the
// moments of inertia times the spin rates stay within double's range.
constexpr double smallest_extent = 1e-12;

vec3<double> minus(const vec3<double>& a, const vec3<double>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The unit sphere sampled by an octahedron subdivided four times (1,026 vertices).
std::vector<vec3<double>> sphere_points() {
  std::vector<vec3<double>> p{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<int, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < 4; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      if (const auto found = middle.find(key); found != middle.end()) return found->second;
      const auto &x = p[static_cast<std::size_t>(i)], &y = p[static_cast<std::size_t>(j)];
      const vec3<double> m{x[0] + y[0], x[1] + y[1], x[2] + y[2]};
      const double n = norm(m);
      p.push_back({m[0] / n, m[1] / n, m[2] / n});
      return middle[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : f) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca}), finer.push_back({ab, t[1], bc}), finer.push_back({ca, bc, t[2]}), finer.push_back({ab, bc, ca});
    }
    f = std::move(finer);
  }
  return p;
}

// The distance from p to the triangle (a, b, c): the closest point by its Voronoi region.
double distance_to_triangle(const vec3<double>& p, const vec3<double>& a, const vec3<double>& b, const vec3<double>& c) {
  using models::dot;
  const auto ab = minus(b, a), ac = minus(c, a), ap = minus(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(ap);
  const auto bp = minus(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(bp);
  const auto cp = minus(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(cp);
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  vec3<double> q;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    q = {a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]};
  } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    q = {a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]};
  } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    q = {b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])};
  } else {
    const double denom = 1 / (va + vb + vc), v = vb * denom, w = vc * denom;
    q = {a[0] + v * ab[0] + w * ac[0], a[1] + v * ab[1] + w * ac[1], a[2] + v * ab[2] + w * ac[2]};
  }
  return norm(minus(p, q));
}

// Whether p (principal frame) lies inside the body.
bool inside(const binary_body& b, const vec3<double>& p) {
  if (norm(p) > b.bounding_radius) return false;
  if (norm(p) < b.inner_radius) return true;
  if (b.kind == "ellipsoid") {
    double s = 0;
    for (std::size_t k = 0; k < 3; ++k) s += p[k] * p[k] / (b.semi_axes[k] * b.semi_axes[k]);
    return s <= 1;
  }
  // the winding number: the solid angles of the facets seen from p (Van Oosterom & Strackee 1983)
  double total = 0;
  for (const auto& t : b.shape.facets) {
    const auto x = minus(b.shape.vertices[static_cast<std::size_t>(t[0])], p), y = minus(b.shape.vertices[static_cast<std::size_t>(t[1])], p),
               z = minus(b.shape.vertices[static_cast<std::size_t>(t[2])], p);
    const double lx = norm(x), ly = norm(y), lz = norm(z);
    const double numerator = models::dot(x, models::cross(y, z));
    const double denominator = lx * ly * lz + models::dot(x, y) * lz + models::dot(x, z) * ly + models::dot(y, z) * lx;
    total += 2 * std::atan2(numerator, denominator);
  }
  return total > 2 * std::numbers::pi;
}

}  // namespace

models::polyhedron parse_shape_model(const std::string& text, const std::string& name) {
  models::polyhedron p;
  std::istringstream in(text);
  std::string line;
  long line_number = 0;
  const auto refuse = [&](const std::string& why) { throw bad_input(name + ", line " + std::to_string(line_number) + ": " + why); };
  const auto finite_vertex = [&](std::istringstream& words) { return shape_formats::vertex_of(words, refuse); };
  const auto sized = [&](models::polyhedron&& shape) {
    if (shape.vertices.empty()) return std::move(shape);
    double extent = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto [low, high] = std::minmax_element(shape.vertices.begin(), shape.vertices.end(), [&](const auto& a, const auto& b) { return a[i] < b[i]; });
      extent = std::max(extent, (*high)[i] - (*low)[i]);
    }
    if (extent < smallest_extent)
      throw bad_input(name + ": the vertices span " + schemes::message_number(extent) + " km, out of range (at least " + schemes::message_number(smallest_extent) +
                      " km)");
    return std::move(shape);
  };
  // the plain form starts with two counts; ICQ with Q alone; OBJ with `v`, `f`, `#`, `o`, `g`, … lines
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  std::size_t first = 0;
  while (first < lines.size() && lines[first].find_first_not_of(" \t\r") == std::string::npos) ++first;
  if (first < lines.size() && shape_formats::looks_like_icq(lines[first])) return sized(shape_formats::parse_icq_shape(lines, first, name));
  long n_vertices = -1, n_facets = -1;
  if (first < lines.size()) {
    std::istringstream words(lines[first]);
    if (words >> n_vertices >> n_facets) {
      std::string extra;
      if (words >> extra) n_vertices = n_facets = -1;
    } else {
      n_vertices = n_facets = -1;
    }
  }
  if (n_vertices >= 0) {  // the plain form
    if (n_vertices < 4 || n_facets < 4 || n_vertices > 50'000'000 || n_facets > 100'000'000)
      throw bad_input(name + ": the counts " + std::to_string(n_vertices) + " " + std::to_string(n_facets) + " do not describe a closed solid");
    std::size_t i = first + 1;
    for (long k = 0; k < n_vertices + n_facets; ++k, ++i) {
      while (i < lines.size() && lines[i].find_first_not_of(" \t\r") == std::string::npos) ++i;
      line_number = static_cast<long>(i) + 1;
      if (i >= lines.size()) throw bad_input(name + ": the file ends before its " + std::to_string(n_vertices) + " vertices and " + std::to_string(n_facets) + " facets");
      std::istringstream words(lines[i]);
      if (k < n_vertices) {
        p.vertices.push_back(finite_vertex(words));
      } else {
        std::array<long, 3> f{};
        for (auto& x : f)
          if (!(words >> x)) refuse("a facet needs three vertex numbers");
        p.facets.push_back({static_cast<int>(std::clamp<long>(f[0] - 1, -1, INT32_MAX)), static_cast<int>(std::clamp<long>(f[1] - 1, -1, INT32_MAX)),
                            static_cast<int>(std::clamp<long>(f[2] - 1, -1, INT32_MAX))});
      }
    }
    return sized(std::move(p));
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    line_number = static_cast<long>(i) + 1;
    std::istringstream words(lines[i]);
    std::string tag;
    if (!(words >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      p.vertices.push_back(finite_vertex(words));
    } else if (tag == "f") {
      std::vector<long> ids;
      std::string item;
      while (words >> item) {
        // "7", "7/1", "7//3", "7/1/3": the vertex is the first number; negative counts from the end
        const auto slash = item.find('/');
        long id = 0;
        try {
          std::size_t used = 0;
          id = std::stol(item.substr(0, slash), &used);
          if (used != item.substr(0, slash).size()) refuse("'" + one_line(item) + "' is not a vertex number");
        } catch (const std::logic_error&) {
          refuse("'" + one_line(item) + "' is not a vertex number");
        }
        if (id < -static_cast<long>(p.vertices.size()))
          refuse("'" + one_line(item) + "' counts back past the first vertex (" + std::to_string(p.vertices.size()) + " so far)");
        ids.push_back(id < 0 ? static_cast<long>(p.vertices.size()) + id : id - 1);
      }
      if (ids.size() != 3) refuse("facets must be triangles (" + std::to_string(ids.size()) + " vertices)");
      p.facets.push_back({static_cast<int>(std::clamp<long>(ids[0], -1, INT32_MAX)), static_cast<int>(std::clamp<long>(ids[1], -1, INT32_MAX)),
                          static_cast<int>(std::clamp<long>(ids[2], -1, INT32_MAX))});
    } else if (tag == "vn" || tag == "vt" || tag == "o" || tag == "g" || tag == "s" || tag == "usemtl" || tag == "mtllib") {
      continue;
    } else {
      refuse("'" + one_line(tag) + "' is neither a vertex (v) nor a facet (f) line of a Wavefront OBJ file, nor the plain form's counts");
    }
  }
  return sized(std::move(p));
}

binary_body binary_shape_named(const std::string& spec, const std::string& option) {
  binary_body b;
  b.spec = spec;
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon), rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (kind == "ellipsoid") {
    const auto axes = positive_numbers(rest, option + " ellipsoid: a semi-axis");
    if (axes.size() != 3) throw bad_input(option + ": ellipsoid:a,b,c takes three semi-axes in km, got '" + one_line(spec) + "'");
    if (!(axes[0] >= axes[1] && axes[1] >= axes[2]))
      throw bad_input(option + ": the semi-axes must satisfy a >= b >= c (a along the body x), got '" + one_line(spec) + "'");
    b.kind = kind;
    b.semi_axes = {axes[0], axes[1], axes[2]};
    b.volume = 4 * std::numbers::pi / 3 * axes[0] * axes[1] * axes[2];
    b.bounding_radius = axes[0];
    b.inner_radius = axes[2];
    for (const auto& u : sphere_points()) b.surface.push_back({axes[0] * u[0], axes[1] * u[1], axes[2] * u[2]});
    return b;
  }
  if (kind == "polyhedron" || kind == "gubas") {
    const auto text_of = [&](const std::string& path) {
      try {
        return read_bounded_file(path, shape_file_limit);
      } catch (const std::runtime_error& e) {
        throw bad_input(option + ": " + one_line(e.what()));
      }
    };
    std::string name;
    models::polyhedron shape;
    if (kind == "polyhedron") {
      if (rest.empty()) throw bad_input(option + ": polyhedron:FILE names a shape model file");
      name = option + " " + printable_path(rest);
      shape = parse_shape_model(text_of(rest), name);
    } else {
      // GUBAS's pair of files, in metres: the vertices, then after the first comma the facets
      const auto comma = rest.find(',');
      if (rest.empty() || comma == std::string::npos || comma == 0 || comma + 1 == rest.size())
        throw bad_input(option + ": gubas:VERTICES,FACETS names GUBAS's vertex and facet files, got '" + one_line(spec) + "'");
      const std::string vertices = rest.substr(0, comma), facets = rest.substr(comma + 1);
      name = option + " " + printable_path(vertices);
      shape = shape_formats::parse_gubas_shape(text_of(vertices), text_of(facets), name, option + " " + printable_path(facets));
    }
    models::polyhedron_integrals<double> integrals;
    try {
      integrals = models::polyhedron_body<double>(shape, 1.0);
    } catch (const std::invalid_argument& e) {
      throw bad_input(name + ": " + e.what());
    }
    b.kind = "polyhedron";  // GUBAS's files too: a polyhedron once read
    b.volume = integrals.volume;
    b.axes = integrals.axes;
    b.centroid = integrals.centroid;
    b.body = integrals.body;  // at unit density: scaled by with_density / with_mass
    for (auto& v : shape.vertices) v = transpose(b.axes) * minus(v, b.centroid);
    for (const auto& v : shape.vertices) b.bounding_radius = std::max(b.bounding_radius, norm(v));
    b.inner_radius = b.bounding_radius;
    for (const auto& t : shape.facets)
      b.inner_radius = std::min(b.inner_radius, distance_to_triangle({0, 0, 0}, shape.vertices[static_cast<std::size_t>(t[0])],
                                                                     shape.vertices[static_cast<std::size_t>(t[1])], shape.vertices[static_cast<std::size_t>(t[2])]));
    b.surface = shape.vertices;
    b.shape = std::move(shape);
    if (!inside(b, {0, 0, 0})) b.inner_radius = 0;  // a centre of mass outside the body (a bent shape): no inner ball
    return b;
  }
  throw bad_input(option + ": '" + one_line(spec) + "' is neither ellipsoid:a,b,c (km), polyhedron:FILE nor gubas:VERTICES,FACETS");
}

binary_body with_density(binary_body b, double density) {
  b.density = density;
  const double mass = density * m3_per_km3 * b.volume;
  if (b.kind == "ellipsoid") {
    b.body = models::ellipsoid_body(mass, b.semi_axes[0], b.semi_axes[1], b.semi_axes[2], 4);
  } else {
    const double scale = density * m3_per_km3;  // the integrals were taken at unit density (kg/km³)
    b.body.mass = mass;
    for (auto& x : b.body.inertia.a) x *= scale;
    for (auto& x : b.body.third) x *= scale;
    for (auto& x : b.body.fourth) x *= scale;
    for (auto& x : b.body.moments) x *= scale;
  }
  return b;
}

binary_body with_degree(binary_body b, int degree) {
  if (degree <= 4 || b.body.degree >= degree) return b;
  if (b.kind == "ellipsoid") {
    b.body.moments = models::ellipsoid_moments(b.body.mass, b.semi_axes[0], b.semi_axes[1], b.semi_axes[2], degree);
  } else {
    // the shape is kept in its principal frame about its centroid
    b.body.moments = models::polyhedron_monomial_moments<double>(b.shape, {}, models::mat3<double>::identity(), degree);
    for (auto& x : b.body.moments) x *= b.density * m3_per_km3;
  }
  b.body.degree = degree;
  return b;
}

binary_body with_mass(binary_body b, double mass) { return with_density(std::move(b), mass / (m3_per_km3 * b.volume)); }

bool bodies_touch(const binary_body& primary, const models::mat3<double>& Q1, const binary_body& secondary, const models::mat3<double>& Q2,
                  const models::vec3<double>& r) {
  const double d = norm(r);
  if (d > primary.bounding_radius + secondary.bounding_radius) return false;
  if (d < primary.inner_radius + secondary.inner_radius) return true;
  // secondary's points in the primary's frame: Q1ᵀ (r + Q2 p); primary's in the secondary's: Q2ᵀ (Q1 p − r)
  const auto Q1t = transpose(Q1), Q2t = transpose(Q2);
  for (const auto& p : secondary.surface) {
    const auto q = Q2 * p;
    if (inside(primary, Q1t * vec3<double>{r[0] + q[0], r[1] + q[1], r[2] + q[2]})) return true;
  }
  for (const auto& p : primary.surface) {
    const auto q = Q1 * p;
    if (inside(secondary, Q2t * vec3<double>{q[0] - r[0], q[1] - r[1], q[2] - r[2]})) return true;
  }
  return false;
}

const std::vector<binary_system_preset>& binary_system_presets() {
  static const std::vector<binary_system_preset> presets = {
      // Agrusa et al. (2020)'s benchmark parameters were not available to us; these are those of the public
      // GUBAS example configuration (fork meyeralexj/gubas, example/hou_config.cfg): the secondary's
      // semi-axes 103.16 × 79.35 × 66.13 m, density 2.203111036687207 g/cm³ for both bodies, separation
      // 1200 m, primary spin 7.72269580528e-4 rad/s (8136 s = 2.26 h). The example's primary is a shape
      // model (Didymos_A, 1000 vertices); the ellipsoid here is the Didymos-size one of GUBAS's
      // Perturbed-Model configuration (398.88 × 391.30 × 383.48 m).
      {"didymos", "ellipsoid:0.39888,0.39130,0.38348", "ellipsoid:0.10316,0.07935,0.06613", 2203.111036687207, 2203.111036687207, 1.2,
       8136.0 / 3600, "GUBAS example configuration (secondary, density, separation, primary spin); GUBAS Perturbed-Model configuration (primary ellipsoid)"},
  };
  return presets;
}

const binary_system_preset& binary_system_named(const std::string& name) {
  std::string names;
  for (const auto& p : binary_system_presets()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw bad_input("--system: no binary system is called '" + one_line(name) + "' (known: " + names + ")");
}

}  // namespace rotlie::runs
