#pragma once
// The configurational temperature of rigid bodies (Jepps, Ayton & Evans 2000; for rigid molecules
// Chialvo & Cummings): for any vector field X whose divergence vanishes under the configurational
// measure's base (translations of a centre; rotations of a body about lab axes, X_k f(Q) = d/ds
// f(exp(s ê_k) Q), which keep the Haar measure), integration by parts gives
//   ⟨(X V)²⟩ = k_B T ⟨X X V⟩,
// so k_B T_conf = ⟨Σ|F|²⟩ / ⟨∇²V⟩ from the centres and ⟨Σ|τ|²⟩ / ⟨Σ_k X_k² V⟩ from the rotations, the
// torques being −X_k V. The Laplacians are estimated without second derivatives of the potential
// (Hutchinson's trace estimator): for z with independent ±1 components E[zᵀ H z] = tr H, and zᵀ H z
// is the central difference of −z·F (or −z·τ) along z, two force evaluations at ±ε. Any potential
// that gives forces and torques serves.
#include <cmath>
#include <cstdint>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scene_contracts.hpp"
#include "rotlie/models/seeded_random.hpp"

namespace rotlie::models {

/// One configuration's sums: Σ|F|², Σ|τ|² and the two Laplacian estimates.
struct configurational_sample {
  double force_squared = 0, torque_squared = 0, translation_laplacian = 0, rotation_laplacian = 0;
};

namespace detail {
// exp([v]×) by Rodrigues's formula.
inline mat3<double> rotation_of(const vec3<double>& v) {
  const double a = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  mat3<double> R = mat3<double>::identity();
  if (a == 0) return R;
  const double s = std::sin(a) / a, c = (1 - std::cos(a)) / (a * a);
  const double K[3][3] = {{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double K2 = 0;
      for (int k = 0; k < 3; ++k) K2 += K[i][k] * K[k][j];
      R(i, j) += s * K[i][j] + c * K2;
    }
  return R;
}
}  // namespace detail

/// The sums at `bodies` (forces and torques there given), the Laplacians probed along one random ±1
/// direction of each kind with steps eps_q (length) and eps_r (radians); `scratch` is reused.
template <class Potential>
configurational_sample probe_configurational(const Potential& potential, const std::vector<rigid_body_state<double>>& bodies,
                                             const std::vector<vec3<double>>& force, const std::vector<vec3<double>>& torque,
                                             seeded_random& random, std::vector<rigid_body_state<double>>& scratch,
                                             double eps_q = 1e-4, double eps_r = 1e-4) {
  configurational_sample c;
  const std::size_t n = bodies.size();
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) c.force_squared += force[i][d] * force[i][d], c.torque_squared += torque[i][d] * torque[i][d];
  std::vector<vec3<double>> z(n), f(n), tau(n), f_minus(n), tau_minus(n);
  auto sign = [&] { return random.uniform() < 0.5 ? -1.0 : 1.0; };
  for (int kind = 0; kind < 2; ++kind) {
    for (auto& zi : z) zi = {sign(), sign(), sign()};
    const double eps = kind == 0 ? eps_q : eps_r;
    for (const double side : {1.0, -1.0}) {
      scratch = bodies;
      for (std::size_t i = 0; i < n; ++i) {
        if (kind == 0)
          for (int d = 0; d < 3; ++d) scratch[i].q[d] += side * eps * z[i][d];
        else
          scratch[i].rot.Q = detail::rotation_of({side * eps * z[i][0], side * eps * z[i][1], side * eps * z[i][2]}) * bodies[i].rot.Q;
      }
      potential_at(potential, scratch, side > 0 ? f : f_minus, side > 0 ? tau : tau_minus, 0.0);
    }
    double d = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        d -= z[i][k] * (kind == 0 ? f[i][k] - f_minus[i][k] : tau[i][k] - tau_minus[i][k]);
    (kind == 0 ? c.translation_laplacian : c.rotation_laplacian) = d / (2 * eps);
  }
  return c;
}

}  // namespace rotlie::models
