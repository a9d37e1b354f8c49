#include "orientation.hpp"

#include <cmath>
#include <utility>

#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::runs::shape_formats {

bool turn_outward(models::polyhedron& p) {
  if (p.vertices.empty()) return false;
  // about the vertices' mean, for less cancellation than about a far origin
  models::vec3<double> mean{};
  for (const auto& v : p.vertices)
    for (std::size_t k = 0; k < 3; ++k) mean[k] += v[k] / static_cast<double>(p.vertices.size());
  double volume = 0;
  for (const auto& f : p.facets) {
    models::vec3<double> corner[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto id = static_cast<std::size_t>(f[k]);
      if (id >= p.vertices.size()) return true;  // a facet naming a vertex the model lacks: polyhedron_body names it
      for (std::size_t c = 0; c < 3; ++c) corner[k][c] = p.vertices[id][c] - mean[c];
    }
    volume += models::dot(corner[0], models::cross(corner[1], corner[2])) / 6;
  }
  if (!(std::abs(volume) > 0) || !std::isfinite(volume)) return false;
  if (volume < 0)
    for (auto& f : p.facets) std::swap(f[1], f[2]);
  return true;
}

}  // namespace rotlie::runs::shape_formats
