#pragma once
// A run's trajectory for plotting: every K steps from the start, the time, one body's attitude and
// body-frame angular momentum, and the energies, in double whatever the run's scalar.
#include <array>
#include <cstddef>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

/// The most samples a trajectory keeps (10⁷ samples of 15 doubles: 1.2 GB); front ends refuse more.
inline constexpr double max_trajectory_samples = 1e7;

struct md_trajectory {
  long every = 0;                         ///< steps between samples; 0: none recorded
  std::vector<double> t_ps;               ///< time from the start
  std::vector<std::array<double, 9>> Q;   ///< body 0's attitude, row-major (columns the body axes)
  std::vector<std::array<double, 3>> G;   ///< body 0's angular momentum in its own frame
  std::vector<double> energy, potential;  ///< K + V and V, in the scene's energy unit

  template <class T>
  void record(double t, const rigid_body_state<T>& body, const T& E, const T& V) {
    t_ps.push_back(t);
    std::array<double, 9> q;
    for (std::size_t i = 0; i < 9; ++i) q[i] = static_cast<double>(body.rot.Q.a[i]);
    Q.push_back(q);
    G.push_back({static_cast<double>(body.rot.G[0]), static_cast<double>(body.rot.G[1]), static_cast<double>(body.rot.G[2])});
    energy.push_back(static_cast<double>(E));
    potential.push_back(static_cast<double>(V));
  }
};

}  // namespace rotlie::models
