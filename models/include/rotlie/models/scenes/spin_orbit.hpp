#pragma once
// The spin–orbit scene (Touma & Wisdom 1994; Wisdom, Peale & Mignard 1984): one triaxial body with
// principal moments A ≤ B ≤ C on a fixed Kepler orbit (kepler_orbit.hpp, G M = 1, a = 1, n = 1)
// about a point mass, with no back-reaction on the orbit. The point mass lies along ±u, u = (cos f,
// sin f, 0) in the inertial frame; with û = Qᵀu in the body frame, MacCullagh's formula keeps of the
// potential only what turns the body,
//   V(Q, t) = (3 G M / 2 r³) ûᵀ I û,       torque N = (3 G M / r³) û × (I û)   (body frame),
// (the terms −GM m/r − GM (A + B + C)/2r³ depend on time alone and move nothing). In the plane
// (rotation θ about z) this is θ'' = −(3/2) ((B − A)/C) r⁻³ sin 2(θ − f), Wisdom et al.'s eq. (1).
// Units are unit_system::natural(); the body's translation is not modelled (no force).
#include <cmath>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/kepler_orbit.hpp"

namespace rotlie::models {

/// The quadrupole torque of the point mass at the orbit's time: a time-dependent torque_potential.
template <class T>
class spin_orbit_tide {
 public:
  spin_orbit_tide(const vec3<T>& moments, const T& e) : I_(moments), orbit_(e) {}

  bool acts() const { return true; }
  const kepler_orbit<T>& orbit() const { return orbit_; }
  const vec3<T>& moments() const { return I_; }

  T evaluate(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque, const T& t) const {
    const orbit_point<T> o = orbit_.at(t);
    const T k = 3 / (o.r * o.r * o.r);
    const vec3<T> u{o.cos_f, o.sin_f, T(0)};
    T V = 0;
    for (std::size_t n = 0; n < bodies.size(); ++n) {
      const auto& Q = bodies[n].rot.Q;
      const vec3<T> ub = transpose(Q) * u;
      const vec3<T> Iu{I_[0] * ub[0], I_[1] * ub[1], I_[2] * ub[2]};
      const vec3<T> N = cross(ub, Iu);
      torque[n] = Q * vec3<T>{k * N[0], k * N[1], k * N[2]};
      force[n] = vec3<T>{};
      V += k * dot(ub, Iu) / 2;
    }
    return V;
  }

  /// The body-frame torque alone (the right-hand side of the general-purpose integrators).
  vec3<T> body_torque(const mat3<T>& Q, const T& t) const {
    const orbit_point<T> o = orbit_.at(t);
    const T k = 3 / (o.r * o.r * o.r);
    const vec3<T> ub = transpose(Q) * vec3<T>{o.cos_f, o.sin_f, T(0)};
    const vec3<T> N = cross(ub, vec3<T>{I_[0] * ub[0], I_[1] * ub[1], I_[2] * ub[2]});
    return {k * N[0], k * N[1], k * N[2]};
  }

  /// V without its isotropic part (3/2r³) A, which depends on time alone and turns nothing: the
  /// potential whose time dependence the extended phase space has to account for.
  T anisotropic_potential(const mat3<T>& Q, const T& t) const {
    const orbit_point<T> o = orbit_.at(t);
    const vec3<T> ub = transpose(Q) * vec3<T>{o.cos_f, o.sin_f, T(0)};
    return 3 / (2 * o.r * o.r * o.r) * ((I_[1] - I_[0]) * ub[1] * ub[1] + (I_[2] - I_[0]) * ub[2] * ub[2]);
  }

  /// ∂/∂t of anisotropic_potential at a fixed attitude: r and f move (ṙ = e sin f/√(1−e²),
  /// ḟ = √(1−e²)/r², n = a = 1), û turns with u' = ḟ (−sin f, cos f, 0).
  T anisotropic_potential_rate(const mat3<T>& Q, const T& t) const {
    const orbit_point<T> o = orbit_.at(t);
    const vec3<T> ub = transpose(Q) * vec3<T>{o.cos_f, o.sin_f, T(0)};
    const vec3<T> vb = transpose(Q) * vec3<T>{-o.sin_f, o.cos_f, T(0)};
    const T k = 3 / (o.r * o.r * o.r);
    const T r_dot = orbit_.eccentricity() * o.sin_f / orbit_.root();
    const T f_dot = orbit_.root() / (o.r * o.r);
    const T dB = I_[1] - I_[0], dC = I_[2] - I_[0];
    return -3 * k * r_dot / o.r / 2 * (dB * ub[1] * ub[1] + dC * ub[2] * ub[2]) + k * f_dot * (dB * ub[1] * vb[1] + dC * ub[2] * vb[2]);
  }

 private:
  vec3<T> I_;
  kepler_orbit<T> orbit_;
};

/// The initial attitude and spin of the command line's contract: the principal axes A, B, C along
/// x, y, z rotated by theta0 about z, then tilted by the obliquity about x; spin omega0 (units of n)
/// about the body's C axis.
template <class T>
body_state<T> spin_orbit_start(const vec3<T>& moments, const T& theta0, const T& omega0, const T& obliquity) {
  body_state<T> s;
  s.Q = rotation(vec3<T>{1, 0, 0}, obliquity) * rotation(vec3<T>{0, 0, 1}, theta0);
  s.G = {T(0), T(0), moments[2] * omega0};
  return s;
}

/// The scene's state: one body at the origin (no translation), time 0.
template <class T>
rigid_bodies_state<T> spin_orbit_state(const body_state<T>& rot) {
  rigid_bodies_state<T> x;
  rigid_body_state<T> b;
  b.rot = rot;
  x.bodies.push_back(b);
  return x;
}

/// The energy T + V(t) of the spin (kinetic energy of rotation and the potential above).
template <class T>
T spin_orbit_energy(const spin_orbit_tide<T>& tide, const body_state<T>& s, const T& t) {
  std::vector<rigid_body_state<T>> one(1);
  one[0].rot = s;
  std::vector<vec3<T>> f(1), tau(1);
  return kinetic_energy(tide.moments(), s.G) + tide.evaluate(one, f, tau, t);
}

/// On a circular orbit (e = 0) the potential is steady in the frame turning with the orbit (n = 1),
/// and the Jacobi-type integral J = T + V − n L_z is conserved, L_z = (Q G)_z the inertial spin's z
/// component. A splitting whose flows are each invariant under (Q, t) → (R_z(α) Q, t + α) keeps
/// L_z + e (e the momentum conjugate to t) exactly, so J only oscillates for a symplectic method.
template <class T>
T spin_orbit_jacobi(const spin_orbit_tide<T>& tide, const body_state<T>& s, const T& t) {
  const vec3<T> L = s.Q * s.G;
  return spin_orbit_energy(tide, s, t) - L[2];
}

/// The angle of the body's A axis in the inertial xy plane (θ of the planar problem when the
/// obliquity is 0), in (−π, π].
template <class T>
T spin_angle(const body_state<T>& s) {
  using std::atan2;
  return atan2(s.Q(1, 0), s.Q(0, 0));
}

}  // namespace rotlie::models
