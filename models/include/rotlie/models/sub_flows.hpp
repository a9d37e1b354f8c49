#pragma once
// Exact flows of the parts of H (LV eqs. 4–9). The flow of c·G_k²/2 for time t rotates the body
// about its axis k by θ = c G_k t: G → R_k(−θ) G and Q → Q R_k(θ) (G_k is constant on it). The flow
// of G²/(2I) rotates the attitude about G by |G| t / I and leaves G alone; it commutes with all
// the others, which is why an RS step can gather it into one rotation (section 3.1.2).
#include "rotlie/models/rigid_body.hpp"

namespace rotlie::models {

/// Flow of rate·G_k²/2 for time t (rate = 1/I_k for A, B, C; 1/I_k − 1/I_m for R, S).
template <class T>
inline void rotate_about_axis(body_state<T>& s, int k, const T& rate, const T& t) {
  using std::cos;
  using std::sin;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const T theta = rate * s.G[static_cast<std::size_t>(k)] * t;
  const T c = cos(theta), sn = sin(theta);
  const T gi = s.G[static_cast<std::size_t>(i)], gj = s.G[static_cast<std::size_t>(j)];
  s.G[static_cast<std::size_t>(i)] = c * gi + sn * gj;
  s.G[static_cast<std::size_t>(j)] = c * gj - sn * gi;
  for (int r = 0; r < 3; ++r) {
    const T qi = s.Q(r, i), qj = s.Q(r, j);
    s.Q(r, i) = c * qi + sn * qj;
    s.Q(r, j) = c * qj - sn * qi;
  }
}

/// Flow of G²/(2I) for time t: Q → Q · rotation(G/|G|, |G| t / I).
template <class T>
inline void rotate_about_momentum(body_state<T>& s, const T& inverse_moment, const T& t) {
  using std::sqrt;
  const T g = sqrt(dot(s.G, s.G));
  if (g == 0) return;
  const vec3<T> u{s.G[0] / g, s.G[1] / g, s.G[2] / g};
  s.Q = s.Q * rotation(u, g * inverse_moment * t);
}

}  // namespace rotlie::models
