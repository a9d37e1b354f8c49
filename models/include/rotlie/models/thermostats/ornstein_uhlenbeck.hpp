#pragma once
// The O-step of a Langevin splitting (Leimkuhler & Matthews 2013): the exact flow for time t of
//   dp = −γ p dt + √(2γ m kT) dW,      dG_i = −γ G_i dt + √(2γ I_i kT) dW_i   (G in the body frame),
// with the configuration held: each component is an Ornstein–Uhlenbeck process, so
//   x(t) = a x(0) + √(1 − a²) σ ξ,   a = e^{−γt},   σ² the equilibrium variance (m kT, I_i kT),
// ξ standard normal. Friction and noise act on the body-frame angular momentum, where the rotational
// kinetic energy is diagonal (Davidchack, Handel & Tretyakov 2009 apply theirs to the body frame's
// conjugate momenta as well): the Boltzmann density exp(−Σ G_i²/2I_i kT) is the process's own.
//
// The normals of one body at one O-stage come from their own stream, keyed by (seed, the stage's count,
// the body's index): a run draws the same numbers whatever the number of threads or ranks that share
// its bodies, and a continued run (a restart) needs no generator state, only the count.
#include <cmath>
#include <cstdint>

#include "rotlie/models/seeded_random.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// The normals of body `body` at O-stage number `draw` of a run seeded `seed`.
inline seeded_random langevin_noise(std::uint64_t seed, std::uint64_t draw, std::uint64_t body) {
  std::uint64_t x = draw;
  return seeded_random(seed ^ splitmix64(x), body);
}

/// The decay a = e^{−γt} and the noise's share √(1 − a²), the latter without cancellation for small γt.
struct ou_factors {
  double decay = 1, spread = 0;
};

inline ou_factors ou_factors_for(double friction, double t) {
  const double gt = friction * t;
  return {std::exp(-gt), std::sqrt(-std::expm1(-2 * gt))};
}

/// One component: x ← a x + √(1 − a²) σ ξ.
inline double ornstein_uhlenbeck(double x, const ou_factors& f, double sigma, seeded_random& noise) {
  return f.decay * x + f.spread * sigma * noise.normal();
}

/// One body's O-step: momentum p (σ_p = √(m kT)) and body-frame angular momentum G (σ_i = √(I_i kT)),
/// in the units where the kinetic energy is p²/2m + Σ G_i²/2I_i (kT there, i.e. k_B T / mvv2e).
template <class Noise>
void langevin_body(vec3<double>& p, vec3<double>& G, const ou_factors& f, double sigma_p, const vec3<double>& sigma_G, Noise& noise) {
  for (int i = 0; i < 3; ++i) p[i] = ornstein_uhlenbeck(p[i], f, sigma_p, noise);
  for (int i = 0; i < 3; ++i) G[i] = ornstein_uhlenbeck(G[i], f, sigma_G[i], noise);
}

}  // namespace rotlie::models
