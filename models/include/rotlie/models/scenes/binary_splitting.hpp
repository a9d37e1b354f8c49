#pragma once
// Splittings of the full two-body problem for the composition engine (composition.hpp), with a TV
// table (van Zon & Schofield's Strang-TV for SIER2, PEFRL-TV for SIER4):
//   T  the free flight for time c h: the relative drift and each body's free rotation by its rotor
//      (the exact flow, a closed-form rotor, a scheme table solved for that body's moments);
//   V  the kick: v += c h F/μ, Gᵢ += c h Qᵢᵀ Mᵢ, with F and M at the kick's configuration.
// drift::straight splits H = T_orbit + T_rot + U (SIER); drift::kepler splits H = H_Kepler +
// T_rot + (U − U₀), U₀ = −G M₁M₂/r (Wisdom & Holman 1991): T drifts along the point masses' Kepler
// orbit exactly (kepler_drift.hpp) and V kicks with U − U₀ only.
// Each flow keeps the total angular momentum r × μv + Q₁G₁ + Q₂G₂: a drift keeps r × v (a straight
// line, or a central force's orbit) and each QᵢGᵢ (a free rotation); a kick changes it by
// c h (r × F + M₁ + M₂) = 0 (U, and U − U₀, are invariant under a common rotation).
// In floating point the exact rotor keeps QᵢGᵢ only to about ε per flight and not at random, and its
// Q drifts off the rotations by about ε per flight too (measured: QᵀQ − 1 grows steadily, 2e-16 per
// call): over 10⁵ flights a drift of 1e-11. So each free rotation ends by restoring what it keeps:
// Q ← Q (3 − QᵀQ)/2 (one Newton step toward the nearest rotation) and G ← Qᵀ (Q G)_before, changes at
// round-off that leave a random walk of ε per flight.
#include <optional>
#include <stdexcept>
#include <utility>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/tv_stages.hpp"
#include "rotlie/models/scenes/binary_system.hpp"
#include "rotlie/models/scenes/kepler_drift.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::models {

enum class binary_drift { straight, kepler };

/// The state a splitting steps: the pair, its time (each free flight advances it; a time-dependent
/// term kicks at the flight's end), and its forces kept for the next kick while valid.
template <class T>
struct binary_split_state {
  binary_state<T> x;
  T t{};
  mutual_gravity<T> gravity{};
  bool forces_current = false;
};

template <class T, class Rotor>
class binary_splitting : public tv_stages<binary_splitting<T, Rotor>, T> {
 public:
  using scalar = T;
  using state = binary_split_state<T>;
  using typename tv_stages<binary_splitting<T, Rotor>, T>::stage;

  binary_splitting(binary_system<T> system, Rotor primary, Rotor secondary, binary_drift drift)
      : system_(std::move(system)), rotors_{std::move(primary), std::move(secondary)}, drift_(drift) {}

  const binary_system<T>& system() const { return system_; }
  binary_drift drift() const { return drift_; }

  void check(const schemes::scheme_table& table) const {
    if (table.splitting != schemes::split::tv)
      throw std::invalid_argument("scheme table " + schemes::printable_text(table.name) + " is not a TV table (free flight T, kick V)");
  }
  void free_flight(const T& t, state& s) const {
    auto& x = s.x;
    if (drift_ == binary_drift::kepler)
      kepler_drift(x.r, x.v, system_.G() * system_.total_mass(), t);
    else
      for (std::size_t k = 0; k < 3; ++k) x.r[k] += t * x.v[k];
    for (int b = 0; b < 2; ++b) {
      const vec3<T> spin = x.body[b].Q * x.body[b].G;
      rotors_[b].advance(x.body[b], t);
      mat3<T>& Q = x.body[b].Q;
      mat3<T> half_gap = transpose(Q) * Q;  // (3 − QᵀQ)/2
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) half_gap(i, j) = ((i == j ? T(3) : T(0)) - half_gap(i, j)) / 2;
      Q = Q * half_gap;
      x.body[b].G = transpose(Q) * spin;
    }
    s.t += t;
    s.forces_current = false;
  }

  void kick(const T& t, state& s) const {
    if (!s.forces_current) s.gravity = system_.forces(s.x, s.t, drift_ == binary_drift::straight), s.forces_current = true;
    auto& x = s.x;
    const T k = t / system_.reduced_mass();
    for (std::size_t i = 0; i < 3; ++i) x.v[i] += k * s.gravity.F[i];
    for (int b = 0; b < 2; ++b) {
      const vec3<T> torque = transpose(x.body[b].Q) * (b == 0 ? s.gravity.M1 : s.gravity.M2);
      for (std::size_t i = 0; i < 3; ++i) x.body[b].G[i] += t * torque[i];
    }
  }

 private:
  binary_system<T> system_;
  Rotor rotors_[2];
  binary_drift drift_;
};

}  // namespace rotlie::models
