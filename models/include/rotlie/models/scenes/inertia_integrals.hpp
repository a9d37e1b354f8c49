#pragma once
// A rigid body's inertia integrals T^(k) = ∫ ρ^⊗k dm about its centre of mass, in its body frame, up
// to degree 4 (Hou, Scheeres & Xin 2017): the mass (k = 0), the second-degree integrals (carried as
// the inertia tensor I = tr(J)·1 − J of J = T^(2)), the third- and fourth-degree ones as full
// symmetric tensors, flat and row-major (index i₁·3^(k−1) + … + i_k). The first-degree integrals
// vanish about the centre of mass. Homogeneous ellipsoids here; polyhedra in polyhedron_body.hpp.
#include <array>
#include <cstddef>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

constexpr std::size_t power_of_three(int k) { return k == 0 ? 1 : 3 * power_of_three(k - 1); }

/// A rank-k tensor on R³, flat.
template <class T, int K>
using tensor3 = std::array<T, power_of_three(K)>;

/// A rigid body for the mutual gravity: its mass, inertia tensor and, when `degree` is 4 or more, its
/// third- and fourth-degree integrals (all in its body frame, about its centre of mass). `degree` says
/// which integrals are known: 2 for a body given by its inertia alone (higher orders refuse it, unless it
/// is a point). Above degree 4 `moments` holds every degree 0…degree as monomial moments
/// (monomial_moments.hpp), the lower ones equal to the tensors'.
template <class T>
struct gravitating_body {
  T mass{};
  mat3<T> inertia{};
  tensor3<T, 3> third{};
  tensor3<T, 4> fourth{};
  int degree = 2;
  std::vector<T> moments{};
};

/// J = ∫ ρρᵀ dm from the inertia tensor: J = (tr I / 2)·1 − I.
template <class T>
mat3<T> second_moments(const mat3<T>& inertia) {
  const T half_trace = (inertia(0, 0) + inertia(1, 1) + inertia(2, 2)) / 2;
  mat3<T> J;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J(i, j) = (i == j ? half_trace : T(0)) - inertia(i, j);
  return J;
}

/// The tensor in the frame Q maps into: T'_{a…} = Q_{a i} … T_{i…} (each index turned in turn).
template <class T, int K>
tensor3<T, K> rotate_tensor(const mat3<T>& Q, const tensor3<T, K>& t) {
  tensor3<T, K> in = t, out{};
  for (int slot = 0; slot < K; ++slot) {
    const std::size_t stride = power_of_three(K - 1 - slot);
    for (std::size_t index = 0; index < in.size(); ++index) {
      const int a = static_cast<int>(index / stride % 3);
      const std::size_t base = index - static_cast<std::size_t>(a) * stride;
      out[index] = Q(a, 0) * in[base] + Q(a, 1) * in[base + stride] + Q(a, 2) * in[base + 2 * stride];
    }
    in = out;
  }
  return in;
}

/// A homogeneous ellipsoid of semi-axes a, b, c along its body x, y, z: I = (M/5) diag(b² + c², a² + c², a² + b²).
template <class T>
mat3<T> ellipsoid_inertia(const T& mass, const T& a, const T& b, const T& c) {
  mat3<T> I;
  I(0, 0) = mass * (b * b + c * c) / 5;
  I(1, 1) = mass * (a * a + c * c) / 5;
  I(2, 2) = mass * (a * a + b * b) / 5;
  return I;
}

/// The homogeneous ellipsoid with all its integrals to degree 4: the odd ones vanish by symmetry; over
/// the unit ball ⟨x⁴⟩ = 3/35 and ⟨x²y²⟩ = 1/35, scaled by the semi-axes.
template <class T>
gravitating_body<T> ellipsoid_body(const T& mass, const T& a, const T& b, const T& c) {
  gravitating_body<T> body;
  body.mass = mass;
  body.inertia = ellipsoid_inertia(mass, a, b, c);
  const T axes[3] = {a, b, c};
  for (std::size_t index = 0; index < body.fourth.size(); ++index) {
    int count[3] = {0, 0, 0};
    for (std::size_t rest = index, slot = 0; slot < 4; ++slot, rest /= 3) ++count[rest % 3];
    if (count[0] % 2 || count[1] % 2 || count[2] % 2) continue;
    T value = mass;
    for (int k = 0; k < 3; ++k)
      for (int p = 0; p < count[k]; ++p) value *= axes[k];
    const bool one_axis = count[0] == 4 || count[1] == 4 || count[2] == 4;
    body.fourth[index] = one_axis ? 3 * value / 35 : value / 35;
  }
  body.degree = 4;
  return body;
}

}  // namespace rotlie::models
