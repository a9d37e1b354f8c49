#pragma once
// The free rigid body on the numeric side: moments of inertia, state (attitude Q: body → lab,
// columns = body axes in the lab frame; body angular momentum G), Euler's equations
// Ġ = G × ω, Q̇ = Q ω̂ with ω = I⁻¹G, and the invariants that every sub-flow must keep.
#include <limits>
#include <stdexcept>
#include <string>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

template <class T>
struct body_state {
  mat3<T> Q = mat3<T>::identity();
  vec3<T> G{};
};

/// Throws std::invalid_argument unless the moments are finite, positive and satisfy eq. (77).
template <class T>
void validate_moments(const vec3<T>& I) {
  using std::isfinite;
  for (const auto& x : I)
    if (!(x > 0) || !isfinite(static_cast<double>(x)))
      throw std::invalid_argument("moments of inertia must be finite and positive");
  // a flat body (I_k = I_i + I_j) given by rounded moments may break eq. (77) by an ulp or two
  // (0.3 + 0.6 < 0.9 in double): up to 4ε relative it is taken as the flat body it is meant to be
  const T slack = 1 + 4 * std::numeric_limits<T>::epsilon();
  for (int k = 0; k < 3; ++k)
    if (I[static_cast<std::size_t>(k)] > (I[static_cast<std::size_t>((k + 1) % 3)] + I[static_cast<std::size_t>((k + 2) % 3)]) * slack)
      throw std::invalid_argument("moments of inertia violate the triangle inequality of eq. (77)");
}

template <class T>
T kinetic_energy(const vec3<T>& I, const vec3<T>& G) {
  return (G[0] * G[0] / I[0] + G[1] * G[1] / I[1] + G[2] * G[2] / I[2]) / 2;
}

template <class T>
vec3<T> angular_velocity(const vec3<T>& I, const vec3<T>& G) {
  return {G[0] / I[0], G[1] / I[1], G[2] / I[2]};
}

/// Euler's equations with the attitude: the right-hand side used by reference integrators.
template <class T>
void euler_rhs(const vec3<T>& I, const body_state<T>& s, body_state<T>& ds) {
  const vec3<T> w = angular_velocity(I, s.G);
  ds.G = {s.G[1] * w[2] - s.G[2] * w[1], s.G[2] * w[0] - s.G[0] * w[2], s.G[0] * w[1] - s.G[1] * w[0]};
  for (int i = 0; i < 3; ++i) {  // (Q ω̂)_ij with ω̂ = [[0,−w3,w2],[w3,0,−w1],[−w2,w1,0]]
    ds.Q(i, 0) = s.Q(i, 1) * w[2] - s.Q(i, 2) * w[1];
    ds.Q(i, 1) = s.Q(i, 2) * w[0] - s.Q(i, 0) * w[2];
    ds.Q(i, 2) = s.Q(i, 0) * w[1] - s.Q(i, 1) * w[0];
  }
}

}  // namespace rotlie::models
