#pragma once
// What a demanding user checks first in a liquid: no two molecules on top of each other, the
// oxygen–oxygen radial distribution function, the total momentum.
#include <cmath>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/molecule_pair_list.hpp"

namespace rotlie::models {

struct closest_pair {
  double distance = 0;  ///< Å; the search radius when no pair is closer
  long i = -1, j = -1;
};

/// The closest two oxygens (minimum image) among those closer than `radius` (O(N) by cells).
template <class T>
closest_pair closest_oxygens(const std::vector<vec3<T>>& oxygen, const T& L, const T& radius) {
  molecule_pair_list<T> list;
  list.build(oxygen, L, radius);
  closest_pair best{static_cast<double>(radius), -1, -1};
  for (const auto& p : list.pairs()) {
    const vec3<T> d = minimum_image(vec3<T>{oxygen[p.i][0] - oxygen[p.j][0], oxygen[p.i][1] - oxygen[p.j][1], oxygen[p.i][2] - oxygen[p.j][2]}, L);
    const double r = std::sqrt(static_cast<double>(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    if (r < best.distance) best = {r, p.i, p.j};
  }
  return best;
}

/// g_OO(r) on bins of width dr up to r_max (< L/2), accumulated over configurations.
class oxygen_rdf {
 public:
  oxygen_rdf(double r_max, double dr) : r_max_(r_max), dr_(dr), counts_(static_cast<std::size_t>(r_max / dr), 0.0) {}

  template <class T>
  void add(const std::vector<vec3<T>>& oxygen, const T& L) {
    std::vector<vec3<double>> o(oxygen.size());
    for (std::size_t k = 0; k < o.size(); ++k)
      for (int d = 0; d < 3; ++d) o[k][d] = static_cast<double>(oxygen[k][d]);
    list_.build(o, static_cast<double>(L), r_max_);
    for (const auto& p : list_.pairs()) {
      const vec3<double> d = minimum_image(vec3<double>{o[p.i][0] - o[p.j][0], o[p.i][1] - o[p.j][1], o[p.i][2] - o[p.j][2]}, double(L));
      const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      const auto bin = static_cast<std::size_t>(r / dr_);
      if (bin < counts_.size()) counts_[bin] += 2;  // the pair counts for both molecules
    }
    molecules_ = static_cast<double>(oxygen.size());
    volume_ = std::pow(static_cast<double>(L), 3);
    ++frames_;
  }

  /// (r at the bin centre, g) for every bin.
  std::vector<std::pair<double, double>> curve() const {
    std::vector<std::pair<double, double>> g;
    const double density = molecules_ / volume_, pi = 3.14159265358979323846;
    for (std::size_t b = 0; b < counts_.size(); ++b) {
      const double r0 = dr_ * static_cast<double>(b), r1 = r0 + dr_;
      const double shell = 4.0 / 3.0 * pi * (r1 * r1 * r1 - r0 * r0 * r0);
      g.emplace_back(r0 + dr_ / 2, frames_ ? counts_[b] / (static_cast<double>(frames_) * molecules_ * density * shell) : 0.0);
    }
    return g;
  }

 private:
  double r_max_, dr_;
  std::vector<double> counts_;
  molecule_pair_list<double> list_;
  double molecules_ = 0, volume_ = 1;
  long frames_ = 0;
};

/// Σ p over the molecules (g/mol·Å/fs).
template <class T>
vec3<T> total_momentum(const rigid_bodies_state<T>& s) {
  vec3<T> P{};
  for (const auto& b : s.bodies)
    for (int d = 0; d < 3; ++d) P[d] += b.p[d];
  return P;
}

}  // namespace rotlie::models
