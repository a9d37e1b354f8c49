#pragma once
// Bodies made of point masses, for the mutual gravity's tests: their integrals are sums over the points,
// and the mutual potential of two of them is exactly Σ −G mᵢ mⱼ / |xⱼ − xᵢ| (G = 1 here).
#include <cmath>
#include <random>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::test {

struct point_cluster {
  std::vector<long double> m;
  std::vector<models::vec3<long double>> x;  // about the centre of mass, body frame
};

/// `points` masses of about equal size scattered in a box of half-sides size·(1, 0.8, 0.6), total `mass`.
inline point_cluster random_cluster(std::mt19937_64& rng, long double mass, long double size, int points) {
  std::uniform_real_distribution<double> u(-1, 1);
  point_cluster c;
  models::vec3<long double> centre{};
  long double total = 0;
  for (int i = 0; i < points; ++i) {
    c.m.push_back(1 + 0.5L * u(rng));
    c.x.push_back({size * u(rng), 0.8L * size * u(rng), 0.6L * size * u(rng)});
    total += c.m.back();
    for (std::size_t k = 0; k < 3; ++k) centre[k] += c.m.back() * c.x.back()[k];
  }
  for (std::size_t i = 0; i < c.m.size(); ++i) {
    c.m[i] *= mass / total;
    for (std::size_t k = 0; k < 3; ++k) c.x[i][k] -= centre[k] / total;
  }
  return c;
}

/// The clusters' exact mutual potential, body 1 turned by Q1 at the origin and body 2 by Q2 at r.
inline long double exact_cluster_potential(const point_cluster& c1, const models::mat3<long double>& Q1, const point_cluster& c2,
                                           const models::mat3<long double>& Q2, const models::vec3<long double>& r) {
  long double U = 0;
  for (std::size_t i = 0; i < c1.m.size(); ++i)
    for (std::size_t j = 0; j < c2.m.size(); ++j) {
      const auto a = Q1 * c1.x[i], b = Q2 * c2.x[j];
      const long double dx = r[0] + b[0] - a[0], dy = r[1] + b[1] - a[1], dz = r[2] + b[2] - a[2];
      U -= c1.m[i] * c2.m[j] / std::sqrt(dx * dx + dy * dy + dz * dz);
    }
  return U;
}

}  // namespace rotlie::test
