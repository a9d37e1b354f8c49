#pragma once
// The state of N rigid bodies under forces and torques (van Zon & Schofield section III): per body
// the centre q, momentum p and the rotation (Q body → lab, body angular momentum G = Qᵀ L), plus
// the forces at the current configuration, cached between one step's last kick and the next
// step's first (first-same-as-last), and the time t: the coordinate the free flights advance and the
// kicks read, so that a time-dependent potential is evaluated at each kick stage's own time (H(x, t)
// made autonomous by adding t to the phase space). Units: those of the system (unit_system.hpp).
#include <cstdint>
#include <vector>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/models/thermostats/nose_hoover_chain.hpp"
#include "rotlie/models/step_clock.hpp"

namespace rotlie::models {

template <class T>
struct rigid_body_state {
  vec3<T> q{}, p{};
  body_state<T> rot;  ///< (Q, G)
  unsigned type = 0;  ///< the body's type: an index into the system's body types (mass, moments, rotor)
};

/// A thermostat's own state (thermostats/thermostatted_bodies.hpp): the Ornstein–Uhlenbeck stages drawn so
/// far (the noise's key) and the Nosé–Hoover chains on translation and rotation.
struct bath_state {
  std::uint64_t draws = 0;
  /// Σ p²/m and Σ G_i²/I_i (mass·velocity²) right after the last O-stage: BAOAB's mid-step momenta, whose
  /// temperature is the thermostat's own (the step-end momenta of BAOAB are off by O(h²) where forces are stiff)
  double two_K_translation_after_o = 0, two_K_rotation_after_o = 0;
  nose_hoover_chain translation, rotation;
  nose_hoover_chain_state translation_state, rotation_state;
};

template <class T>
struct rigid_bodies_state {
  std::vector<rigid_body_state<T>> bodies;
  T t{};  ///< time, advanced by the free flights
  step_clock<T> clock;  ///< the step count behind t in the engine's steps (t is written from it, never summed)
  // forces at the current configuration (valid while forces_current)
  std::vector<vec3<T>> force, torque;  ///< lab force (kcal/mol/Å), lab torque about the centre (kcal/mol)
  T potential{};                       ///< V at the current configuration and time (kcal/mol)
  bool forces_current = false;
  unsigned long forces_of = 0;  ///< which system's potential the cached forces are of (its identity)
  long force_evaluations = 0;
  bath_state bath;  ///< a thermostat's state (none acts on a system without one)
};

template <class T>
vec3<T> cross(const vec3<T>& a, const vec3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Lab angular momentum of one body about its centre: L = Q G.
template <class T>
vec3<T> lab_spin(const rigid_body_state<T>& b) {
  return b.rot.Q * b.rot.G;
}

/// Total lab angular momentum Σ (q × p + Q G).
template <class T>
vec3<T> total_angular_momentum(const rigid_bodies_state<T>& s) {
  vec3<T> L{};
  for (const auto& b : s.bodies) {
    const vec3<T> orbit = cross(b.q, b.p), spin = lab_spin(b);
    for (std::size_t i = 0; i < 3; ++i) L[i] += orbit[i] + spin[i];
  }
  return L;
}

}  // namespace rotlie::models
