#pragma once
// Molecule pairs within a list radius in a cubic periodic box (minimum image), found through a
// cell list in O(N): the box is cut into c³ cells of side ≥ the list radius, and each molecule
// meets the molecules of its own and the 26 neighbouring cells. With fewer than three cells a side
// (a small box) every pair is tested instead. Pairs (i, j) have i < j and come in a fixed order
// (i ascending, then by cell), so the list is the same on every run.
#include <cmath>
#include <cstdint>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// d − L·round(d/L), componentwise: the minimum image of a separation in a cubic box of side L.
template <class T>
vec3<T> minimum_image(vec3<T> d, const T& L) {
  using std::nearbyint;
  for (auto& x : d) x -= L * nearbyint(x / L);
  return d;
}

template <class T>
class molecule_pair_list {
 public:
  struct pair {
    std::int32_t i, j;
  };

  /// All pairs whose reference points (one per molecule) are closer than `radius` (minimum image).
  void build(const std::vector<vec3<T>>& point, const T& L, const T& radius) {
    using std::floor;
    const int n = static_cast<int>(point.size());
    pairs_.clear();
    const T r2 = radius * radius;
    auto close = [&](int i, int j) {
      const vec3<T> d = minimum_image(vec3<T>{point[i][0] - point[j][0], point[i][1] - point[j][1], point[i][2] - point[j][2]}, L);
      return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < r2;
    };
    const int c = static_cast<int>(floor(L / radius));
    if (c < 3) {
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          if (close(i, j)) pairs_.push_back({i, j});
      return;
    }
    // cells: head-of-chain per cell and next per molecule, filled in descending index so that
    // each chain runs in ascending molecule order
    head_.assign(static_cast<std::size_t>(c) * c * c, -1);
    next_.assign(static_cast<std::size_t>(n), -1);
    cell_.resize(static_cast<std::size_t>(n));
    for (int i = n - 1; i >= 0; --i) {
      int k[3];
      for (int a = 0; a < 3; ++a) {
        T x = point[i][a] / L;
        x -= floor(x);
        k[a] = static_cast<int>(x * c);
        if (k[a] >= c) k[a] = c - 1;  // x rounded to 1
      }
      const int id = (k[0] * c + k[1]) * c + k[2];
      cell_[i] = id;
      next_[i] = head_[id];
      head_[id] = i;
    }
    for (int i = 0; i < n; ++i) {
      const int id = cell_[i], kx = id / (c * c), ky = (id / c) % c, kz = id % c;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const int nb = (((kx + dx + c) % c) * c + (ky + dy + c) % c) * c + (kz + dz + c) % c;
            for (int j = head_[nb]; j >= 0; j = next_[j])
              if (j > i && close(i, j)) pairs_.push_back({i, j});
          }
    }
  }

  const std::vector<pair>& pairs() const { return pairs_; }

 private:
  std::vector<pair> pairs_;
  std::vector<int> head_, next_, cell_;
};

}  // namespace rotlie::models
