#pragma once
// Rigid bodies under forces and torques as a system of the composition engine (van Zon & Schofield
// section III): a TV table binds T to the free flight φ⁽⁰⁾ (eq. 5: q += c h p/m, and the free
// rotation by the rotor) and V to the kick φ⁽¹⁾ (eq. 6: p += c h F, L += c h τ, done on G = Qᵀ L).
// Forces are evaluated only when a kick needs them and the configuration moved since the last
// evaluation, so a table that ends and starts with V costs its V stages minus one (f).
//
// The potential is a torque_potential, each body type's rotor a free_rotor (scene_contracts.hpp).
// A kick evaluates V at the state's time, which the free flights advance: for Strang-TV the two
// half kicks see t_n and t_n + h, as the splitting of H(x, t) + e in the extended phase space asks.
// In a step of the engine the time after each free flight is written from the step count (a
// clocked_system, step_clock.hpp), so that it does not drift; free_flight() called alone adds t.
//
// Several body types: each body's `type` indexes a body_type (mass, moments, its own rotor); the
// scenes of van Zon & Schofield have one. Units are data (unit_system): ftm2v in the kicks, mvv2e
// in the kinetic energy.
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scene_contracts.hpp"
#include "rotlie/models/tv_stages.hpp"
#include "rotlie/models/unit_system.hpp"

namespace rotlie::models {

/// One kind of body in a system: mass, principal moments (the rotor's own) and free rotor.
template <class T, class Rotor>
struct body_type {
  T mass;
  vec3<T> moments;
  Rotor rotor;
};

template <class T, class Potential, class Rotor>
  requires torque_potential<Potential, T> && free_rotor<Rotor, T>
class torqued_rigid_bodies : public tv_stages<torqued_rigid_bodies<T, Potential, Rotor>, T> {
 public:
  using scalar = T;
  using state = rigid_bodies_state<T>;
  using type = body_type<T, Rotor>;
  using typename tv_stages<torqued_rigid_bodies<T, Potential, Rotor>, T>::stage;

  /// One body type in real units: mass m (g/mol) and principal moments I (g/mol·Å², the rotor's own).
  torqued_rigid_bodies(const T& mass, const vec3<T>& moments, Potential potential, Rotor rotor)
      : torqued_rigid_bodies({type{mass, moments, std::move(rotor)}}, std::move(potential), unit_system<T>::real()) {}

  /// Several body types (a body's `type` is its index here), in the given units.
  torqued_rigid_bodies(std::vector<type> types, Potential potential, unit_system<T> units)
      : types_(std::move(types)), potential_(std::move(potential)), units_(units) {
    using std::isfinite;
    if (types_.empty()) throw std::invalid_argument("a system needs at least one body type");
    for (const auto& ty : types_) {
      if (!(ty.mass > 0) || !isfinite(static_cast<double>(ty.mass))) throw std::invalid_argument("the mass must be finite and positive");
      validate_moments(ty.moments);
    }
  }

  /// The first body type's (the only one in a one-type scene).
  const T& mass() const { return types_.front().mass; }
  const vec3<T>& moments() const { return types_.front().moments; }
  const Rotor& rotor() const { return types_.front().rotor; }
  const std::vector<type>& body_types() const { return types_; }
  const unit_system<T>& units() const { return units_; }
  const Potential& potential() const { return potential_; }

  void check(const schemes::scheme_table& table) const {
    if (table.splitting != schemes::split::tv)
      throw std::invalid_argument("scheme table " + schemes::printable_text(table.name) +
                                  " is a free-rotation table: a body under torques needs a TV table (free flight T, kick V)");
  }

  /// φ⁽⁰⁾ for time t: translation, each body type's free rotation and the clock; the forces become stale.
  void free_flight(const T& t, state& x) const {
    // runs of bodies of one type: one division t/m per run, the rotations of a run together
    // (advance_bodies: the exact rotor in double vectorised across them, any other one by one)
    for (std::size_t first = 0; first < x.bodies.size();) {
      const unsigned current = x.bodies[first].type;
      std::size_t end = first;
      while (end < x.bodies.size() && x.bodies[end].type == current) ++end;
      const type& ty = type_of(x.bodies[first]);
      const T v = t / ty.mass;
      for (std::size_t k = first; k < end; ++k)
        for (std::size_t i = 0; i < 3; ++i) x.bodies[k].q[i] += v * x.bodies[k].p[i];
      advance_bodies(ty.rotor, end - first, [&](std::size_t k) -> body_state<T>& { return x.bodies[first + k].rot; }, t);
      first = end;
    }
    x.t += t;
    if (potential_.acts()) x.forces_current = false;
  }

  /// φ⁽¹⁾ for time t: p += t ftm2v F, G += t ftm2v Qᵀτ (the lab torque seen in the body frame), with
  /// F and τ at the state's time.
  void kick(const T& t, state& x) const {
    if (!potential_.acts()) return;
    ensure_forces(x);
    const T k = t * units_.ftm2v;
    for (std::size_t n = 0; n < x.bodies.size(); ++n) {
      auto& b = x.bodies[n];
      const vec3<T>& F = x.force[n];
      const vec3<T> tau = transpose(b.rot.Q) * x.torque[n];
      for (std::size_t i = 0; i < 3; ++i) {
        b.p[i] += k * F[i];
        b.rot.G[i] += k * tau[i];
      }
    }
  }

  /// Evaluates the forces unless they belong to the current configuration and to this system's
  /// potential (a state handed from one system to another never keeps the other's forces). The
  /// vectors are sized once; later calls do not allocate.
  void ensure_forces(state& x) const {
    if (cached(x)) return;
    if (x.force.size() != x.bodies.size()) {
      x.force.assign(x.bodies.size(), vec3<T>{});
      x.torque.assign(x.bodies.size(), vec3<T>{});
    }
    x.potential = potential_at(potential_, x.bodies, x.force, x.torque, x.t);
    x.forces_current = true;
    x.forces_of = potential_id_;
    ++x.force_evaluations;
  }

  /// Kinetic energy (kcal/mol in real units): mvv2e Σ (p²/2m + Σ G_i²/2I_i), each body with its type's m and I.
  T kinetic_energy(const state& x) const {
    T e = 0;
    for (const auto& b : x.bodies) {
      const type& ty = type_of(b);
      e += dot(b.p, b.p) / (2 * ty.mass) + models::kinetic_energy(ty.moments, b.rot.G);
    }
    return units_.mvv2e * e;
  }

  /// V at the state's configuration and time (the cached value when current; else evaluated into
  /// scratch vectors, not counted as a step's force evaluation).
  T potential_energy(const state& x) const {
    if (!potential_.acts()) return T(0);
    if (cached(x)) return x.potential;
    std::vector<vec3<T>> f(x.bodies.size()), tau(x.bodies.size());
    return potential_at(potential_, x.bodies, f, tau, x.t);
  }

  T energy(const state& x) const { return kinetic_energy(x) + potential_energy(x); }

 private:
  bool cached(const state& x) const { return x.forces_current && x.forces_of == potential_id_; }

  const type& type_of(const rigid_body_state<T>& b) const {
    if (b.type >= types_.size())
      throw std::out_of_range("body type " + std::to_string(b.type) + " of a system with " + std::to_string(types_.size()) + " body types");
    return types_[b.type];
  }

  // One identity per constructed system, shared by its copies (they hold the same potential).
  static unsigned long next_potential_id() {
    static std::atomic<unsigned long> last{0};
    return ++last;
  }

  std::vector<type> types_;
  Potential potential_;
  unsigned long potential_id_ = next_potential_id();
  unit_system<T> units_;
};

}  // namespace rotlie::models
