#pragma once
// Rigid bodies under forces and torques as a system of the composition engine (van Zon & Schofield
// section III): a TV table binds T to the free flight φ⁽⁰⁾ (eq. 5: q += c h p/m, and the free
// rotation by the rotor) and V to the kick φ⁽¹⁾ (eq. 6: p += c h F, L += c h τ, done on G = Qᵀ L).
// Forces are evaluated only when a kick needs them and the configuration moved since the last
// evaluation, so a table that ends and starts with V costs its V stages minus one (f).
//
// A Potential P provides
//   T evaluate(const std::vector<rigid_body_state<T>>&, std::vector<vec3<T>>& force,
//              std::vector<vec3<T>>& torque) const     fills the lab forces and torques, returns V
//   bool acts() const                                  false for V = 0: kicks are skipped, nothing evaluated
// A Rotor R provides advance(body_state<T>&, const T& t) const: the free rotation for time t
// (exact_free_rotation, table_rotor, sej4_rotor), with the body's moments bound at construction.
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/real_units.hpp"
#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

template <class T, class Potential, class Rotor>
class torqued_rigid_bodies {
 public:
  using scalar = T;
  using state = rigid_bodies_state<T>;
  struct stage {
    bool kick = false;  ///< V (true) or T
    T c{};              ///< the stage's coefficient
  };

  /// One body type: mass m (g/mol) and principal moments I (g/mol·Å², the rotor's own).
  torqued_rigid_bodies(const T& mass, const vec3<T>& moments, Potential potential, Rotor rotor)
      : mass_(mass), I_(moments), potential_(std::move(potential)), rotor_(std::move(rotor)), ftm2v_(real_units::ftm2v<T>()),
        mvv2e_(real_units::mvv2e<T>()) {
    using std::isfinite;
    if (!(mass_ > 0) || !isfinite(static_cast<double>(mass_))) throw std::invalid_argument("the mass must be finite and positive");
    validate_moments(I_);
  }

  const T& mass() const { return mass_; }
  const vec3<T>& moments() const { return I_; }
  const Potential& potential() const { return potential_; }
  const Rotor& rotor() const { return rotor_; }

  void check(const schemes::scheme_table& table) const {
    if (table.splitting != schemes::split::tv)
      throw std::invalid_argument("scheme table " + schemes::printable_text(table.name) +
                                  " is a free-rotation table: a body under torques needs a TV table (free flight T, kick V)");
  }

  stage bind(const schemes::stage& s, const schemes::scheme_table&) const { return {s.part == 'V', parse_scalar<T>(s.value)}; }

  void apply(const stage& st, const T& h, state& x) const {
    const T t = st.c * h;
    if (st.kick)
      kick(t, x);
    else
      free_flight(t, x);
  }

  std::optional<stage> step_end(const schemes::scheme_table&) const { return std::nullopt; }

  /// Force evaluations per step (first-same-as-last), the unit of h/f in vZS section V.
  int cost(const schemes::scheme_table& table) const { return schemes::force_evaluations(table); }

  /// φ⁽⁰⁾ for time t: translation and the rotor's free rotation; the forces become stale.
  void free_flight(const T& t, state& x) const {
    const T v = t / mass_;
    for (auto& b : x.bodies) {
      for (std::size_t i = 0; i < 3; ++i) b.q[i] += v * b.p[i];
      rotor_.advance(b.rot, t);
    }
    if (potential_.acts()) x.forces_current = false;
  }

  /// φ⁽¹⁾ for time t: p += t ftm2v F, G += t ftm2v Qᵀτ (the lab torque seen in the body frame).
  void kick(const T& t, state& x) const {
    if (!potential_.acts()) return;
    ensure_forces(x);
    const T k = t * ftm2v_;
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
    x.potential = potential_.evaluate(x.bodies, x.force, x.torque);
    x.forces_current = true;
    x.forces_of = potential_id_;
    ++x.force_evaluations;
  }

  /// Kinetic energy, kcal/mol: mvv2e Σ (p²/2m + Σ G_i²/2I_i).
  T kinetic_energy(const state& x) const {
    T e = 0;
    for (const auto& b : x.bodies) e += dot(b.p, b.p) / (2 * mass_) + models::kinetic_energy(I_, b.rot.G);
    return mvv2e_ * e;
  }

  /// V at the state's configuration, kcal/mol (the cached value when current; else evaluated into
  /// scratch vectors, not counted as a step's force evaluation).
  T potential_energy(const state& x) const {
    if (!potential_.acts()) return T(0);
    if (cached(x)) return x.potential;
    std::vector<vec3<T>> f(x.bodies.size()), tau(x.bodies.size());
    return potential_.evaluate(x.bodies, f, tau);
  }

  T energy(const state& x) const { return kinetic_energy(x) + potential_energy(x); }

 private:
  bool cached(const state& x) const { return x.forces_current && x.forces_of == potential_id_; }

  // One identity per constructed system, shared by its copies (they hold the same potential).
  static unsigned long next_potential_id() {
    static std::atomic<unsigned long> last{0};
    return ++last;
  }

  T mass_;
  vec3<T> I_;
  Potential potential_;
  unsigned long potential_id_ = next_potential_id();
  Rotor rotor_;
  T ftm2v_, mvv2e_;
};

}  // namespace rotlie::models
