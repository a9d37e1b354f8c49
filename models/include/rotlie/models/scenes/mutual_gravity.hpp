#pragma once
// The mutual gravity of two rigid bodies (the full two-body problem of binary asteroids), expanded in
// the bodies' inertia integrals and truncated by total degree (Hou, Scheeres & Xin 2017): order 0 is
// the two point masses; order 2 adds each body's second-degree integrals against the other's mass
// (MacCullagh's formula for each body; the first-degree integrals vanish about the centres of mass):
//   U = −G M₁M₂/r − (G/2r³) Σ_{i≠j} M_j (tr I_i − 3 r̂ᵀ I_i r̂),
// I_i = Q_i I_i^body Q_iᵀ the inertia tensor in the inertial frame (Q maps body to inertial
// coordinates). r = x₂ − x₁; F = −∂U/∂r is the force on body 2 (−F on body 1); the torque on body i
// about its own centre, inertial, M_i = (3 G M_j / r⁵) r × (I_i r) (the gravity-gradient torque; the
// same for both signs of r). The total angular momentum r × μv + Σ Q_i I_i^body ω_i is conserved:
// r × F + M₁ + M₂ = 0. Order 4 (the third- and fourth-degree integrals and the products of the two
// bodies' second-degree ones) is not written yet. full_two_body_gravity hands the pair to the md
// engine (md_integrators.hpp): SIER2, SIER4, MRDL with the exact or a dedicated rotor per body.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// A rigid body's mass and its inertia tensor about its centre of mass, in its body frame.
template <class T>
struct gravitating_body {
  T mass{};
  mat3<T> inertia{};
};

/// U, the force on body 2 and each body's torque about its own centre (inertial frame).
template <class T>
struct mutual_gravity {
  T U{};
  vec3<T> F{}, M1{}, M2{};
};

/// A homogeneous ellipsoid of semi-axes a, b, c along its body x, y, z: I = (M/5) diag(b² + c², a² + c², a² + b²).
template <class T>
mat3<T> ellipsoid_inertia(const T& mass, const T& a, const T& b, const T& c) {
  mat3<T> I;
  I(0, 0) = mass * (b * b + c * c) / 5;
  I(1, 1) = mass * (a * a + c * c) / 5;
  I(2, 2) = mass * (a * a + b * b) / 5;
  return I;
}

/// Throws std::invalid_argument unless the expansion is written at this order.
inline void check_gravity_order(int order) {
  if (order != 0 && order != 2) throw std::invalid_argument("mutual gravity: order " + std::to_string(order) + " (0 or 2)");
}

/// The mutual potential, force and torques truncated at `order` (0 or 2).
template <class T>
mutual_gravity<T> mutual_gravity_at(const gravitating_body<T>& b1, const mat3<T>& Q1, const gravitating_body<T>& b2, const mat3<T>& Q2,
                                    const vec3<T>& r, const T& G, int order) {
  check_gravity_order(order);
  using std::sqrt;
  const T r2 = dot(r, r), rn = sqrt(r2), r3 = r2 * rn, r5 = r3 * r2, r7 = r5 * r2;
  mutual_gravity<T> out;
  const T GMM = G * b1.mass * b2.mass;
  out.U = -GMM / rn;
  for (std::size_t k = 0; k < 3; ++k) out.F[k] = -GMM * r[k] / r3;  // −∂U/∂r: attraction toward body 1
  if (order == 0) return out;
  const gravitating_body<T>* bodies[2] = {&b1, &b2};
  const mat3<T>* attitudes[2] = {&Q1, &Q2};
  for (int i = 0; i < 2; ++i) {
    const mat3<T> I = *attitudes[i] * bodies[i]->inertia * transpose(*attitudes[i]);
    const T other = bodies[1 - i]->mass;
    const T trace = I(0, 0) + I(1, 1) + I(2, 2);
    const vec3<T> Ir = I * r;
    const T rIr = dot(r, Ir);
    out.U -= G * other / 2 * (trace / r3 - 3 * rIr / r5);
    // −∂/∂r of that term: −(G M_j / 2) [3 tr I r / r⁵ + 6 I r / r⁵ − 15 (rᵀIr) r / r⁷]
    for (std::size_t k = 0; k < 3; ++k) out.F[k] -= G * other / 2 * (3 * trace * r[k] / r5 + 6 * Ir[k] / r5 - 15 * rIr * r[k] / r7);
    const vec3<T> torque = cross(r, Ir);
    for (std::size_t k = 0; k < 3; ++k) (i == 0 ? out.M1 : out.M2)[k] = 3 * G * other / r5 * torque[k];
  }
  return out;
}

/// The pair as the md engine's potential: bodies 0 and 1 of a rigid_bodies_state, each with its
/// principal moments along its body axes (its type's), positions in the centre-of-mass frame or any.
template <class T>
class full_two_body_gravity {
 public:
  full_two_body_gravity(const T& m1, const vec3<T>& I1, const T& m2, const vec3<T>& I2, const T& G, int order)
      : b1_{m1, principal(I1)}, b2_{m2, principal(I2)}, G_(G), order_(order) {
    check_gravity_order(order);
  }

  bool acts() const { return true; }

  T evaluate(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque) const {
    if (bodies.size() != 2) throw std::invalid_argument("the full two-body problem has two bodies, not " + std::to_string(bodies.size()));
    const vec3<T> r{bodies[1].q[0] - bodies[0].q[0], bodies[1].q[1] - bodies[0].q[1], bodies[1].q[2] - bodies[0].q[2]};
    const auto g = mutual_gravity_at(b1_, bodies[0].rot.Q, b2_, bodies[1].rot.Q, r, G_, order_);
    force[0] = {-g.F[0], -g.F[1], -g.F[2]};
    force[1] = g.F;
    torque[0] = g.M1;
    torque[1] = g.M2;
    return g.U;
  }

 private:
  static mat3<T> principal(const vec3<T>& I) {
    mat3<T> m;
    for (int k = 0; k < 3; ++k) m(k, k) = I[static_cast<std::size_t>(k)];
    return m;
  }
  gravitating_body<T> b1_, b2_;
  T G_;
  int order_;
};

}  // namespace rotlie::models
