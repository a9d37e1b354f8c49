#pragma once
// Rigid bodies at a temperature: a system of the composition engine that adds a thermostat's letters
// to those of the bodies under torques (torqued_rigid_bodies: T the free flight with any rotor, V the
// kick). A table from schemes::thermostatted_table places them:
//   O  the exact Ornstein–Uhlenbeck step on every body's momentum and body-frame angular momentum
//      (ornstein_uhlenbeck.hpp), friction γ: Langevin dynamics, BAOAB or OBABO on Strang-TV;
//   N  the flow of two Nosé–Hoover chains (nose_hoover_chain.hpp), one on the translational and one on
//      the rotational kinetic energy, as LAMMPS's rigid/nvt/small keeps them (Kamberaj, Low & Neal 2005).
// The configuration does not move in O or N: the forces of the last kick stay current. The thermostat's
// own state (the O-stages drawn, the chains) travels in the state's `bath`, so a state copied or held
// continues the same run. In double only (the noise is drawn in double; a chain's kept quantity is a
// double-precision check).
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/thermostats/nose_hoover_chain.hpp"
#include "rotlie/models/thermostats/ornstein_uhlenbeck.hpp"
#include "rotlie/schemes/thermostat_tables.hpp"

namespace rotlie::models {

/// What a thermostat holds the bodies at, in the system's units.
struct thermostat_parameters {
  double kT = 0;            ///< target k_B T in the system's energy units (kcal/mol in real units)
  double friction = 0;      ///< γ of the O-step, 1/time (Langevin)
  double tau = 0;           ///< the chains' period, time (Nosé–Hoover)
  int chain_length = 3;     ///< Nosé–Hoover chain length
  int chain_order = 3;      ///< Suzuki–Yoshida order of the chains' flow (1, 3, 5)
  int chain_iterations = 1; ///< its substeps
  bool momentum_conserved = true;  ///< the chain on translation counts 3N − 3 degrees of freedom (forces sum to zero)
  std::uint64_t seed = 1;   ///< the O-step's noise
};

/// Throws std::invalid_argument, one line, unless the parameters suit the placement's letter.
inline void check_thermostat(const thermostat_parameters& p, schemes::thermostat_placement placement) {
  if (!(p.kT > 0) || !std::isfinite(p.kT)) throw std::invalid_argument("the thermostat's temperature must be positive and finite");
  if (placement == schemes::thermostat_placement::chain) {
    if (!(p.tau > 0) || !std::isfinite(p.tau)) throw std::invalid_argument("the Nose-Hoover chain's period must be positive and finite");
    nose_hoover_chain(1, p.kT, p.tau, p.chain_length, p.chain_order, p.chain_iterations);  // its own checks
  } else if (!(p.friction > 0) || !std::isfinite(p.friction)) {
    throw std::invalid_argument("the Langevin friction must be positive and finite");
  }
}

template <class Bodies>
class thermostatted_bodies {
 public:
  using scalar = typename Bodies::scalar;
  using state = typename Bodies::state;
  static_assert(std::is_same_v<scalar, double>, "thermostats draw their noise in double");

  struct stage {
    char letter = 'T';  ///< T, V (the bodies'), O or N
    double c = 0;
    typename Bodies::stage inner{};
  };

  thermostatted_bodies(Bodies bodies, thermostat_parameters p) : bodies_(std::move(bodies)), p_(p) {}

  const Bodies& bodies() const { return bodies_; }
  const thermostat_parameters& parameters() const { return p_; }

  void check(const schemes::scheme_table& table) const {
    bodies_.check(table);
    bool o = false, n = false;
    for (const auto& s : table.stages) o |= s.part == 'O', n |= s.part == 'N';
    if (!o && !n) throw std::invalid_argument("scheme table " + table.name + " has no thermostat stage (O or N)");
    check_thermostat(p_, n ? schemes::thermostat_placement::chain : schemes::thermostat_placement::middle);
  }

  stage bind(const schemes::stage& s, const schemes::scheme_table& table) const {
    stage st{s.part, parse_scalar<double>(s.value), {}};
    if (!schemes::is_thermostat_letter(s.part)) st.inner = bodies_.bind(s, table);
    return st;
  }
  std::optional<stage> step_end(const schemes::scheme_table&) const { return std::nullopt; }
  int cost(const schemes::scheme_table& table) const { return bodies_.cost(table); }
  double time_coefficient(const stage& st) const { return schemes::is_thermostat_letter(st.letter) ? 0.0 : bodies_.time_coefficient(st.inner); }

  void apply(const stage& st, const double& h, state& x) const {
    if (st.letter == 'O')
      langevin(st.c * h, x);
    else if (st.letter == 'N')
      chains(st.c * h, x);
    else
      bodies_.apply(st.inner, h, x);
  }

  /// The O-step for time t on every body (see ornstein_uhlenbeck.hpp); the stage count advances.
  void langevin(double t, state& x) const {
    const ou_factors f = ou_factors_for(p_.friction, t);
    const double kT = p_.kT / bodies_.units().mvv2e;  // in mass·velocity²
    double two_K_t = 0, two_K_r = 0;
    for (std::size_t n = 0; n < x.bodies.size(); ++n) {
      auto& b = x.bodies[n];
      const auto& ty = bodies_.body_types().at(b.type);
      const vec3<double> sigma_G{std::sqrt(ty.moments[0] * kT), std::sqrt(ty.moments[1] * kT), std::sqrt(ty.moments[2] * kT)};
      auto noise = langevin_noise(p_.seed, x.bath.draws, n);
      langevin_body(b.p, b.rot.G, f, std::sqrt(ty.mass * kT), sigma_G, noise);
      two_K_t += dot(b.p, b.p) / ty.mass;
      for (int i = 0; i < 3; ++i) two_K_r += b.rot.G[i] * b.rot.G[i] / ty.moments[i];
    }
    x.bath.two_K_translation_after_o = two_K_t, x.bath.two_K_rotation_after_o = two_K_r;
    ++x.bath.draws;
  }

  /// The chains' flow for time t: translation and rotation each scaled by their chain's factor.
  void chains(double t, state& x) const {
    ready_chains(x);
    const double s_t = x.bath.translation.advance(x.bath.translation_state, 2 * translational_energy(x), t);
    const double s_r = x.bath.rotation.advance(x.bath.rotation_state, 2 * rotational_energy(x), t);
    for (auto& b : x.bodies)
      for (int i = 0; i < 3; ++i) b.p[i] *= s_t, b.rot.G[i] *= s_r;
  }

  /// Σ p²/2m and Σ G_i²/2I_i in the system's energy units.
  double translational_energy(const state& x) const {
    double e = 0;
    for (const auto& b : x.bodies) e += dot(b.p, b.p) / (2 * bodies_.body_types().at(b.type).mass);
    return bodies_.units().mvv2e * e;
  }
  double rotational_energy(const state& x) const {
    double e = 0;
    for (const auto& b : x.bodies) e += models::kinetic_energy(bodies_.body_types().at(b.type).moments, b.rot.G);
    return bodies_.units().mvv2e * e;
  }
  /// Degrees of freedom of the translation (3N, or 3N − 3 when the forces keep the total momentum) and of
  /// the rotation (3 per body).
  double translational_dof(const state& x) const {
    const double n = 3.0 * static_cast<double>(x.bodies.size());
    return p_.momentum_conserved && x.bodies.size() > 1 ? n - 3 : n;
  }
  double rotational_dof(const state& x) const { return 3.0 * static_cast<double>(x.bodies.size()); }
  /// The kinetic temperatures (in units of the target's k_BT: 1 at equipartition) right after the last
  /// O-stage, translational and rotational.
  std::pair<double, double> temperatures_after_o(const state& x) const {
    const double kT = p_.kT / bodies_.units().mvv2e;
    const double n = 3.0 * static_cast<double>(x.bodies.size());
    return {x.bath.two_K_translation_after_o / (n * kT), x.bath.two_K_rotation_after_o / (n * kT)};
  }

  double kinetic_energy(const state& x) const { return bodies_.kinetic_energy(x); }
  double potential_energy(const state& x) const { return bodies_.potential_energy(x); }
  double energy(const state& x) const { return bodies_.energy(x); }
  /// The energy plus the chains' share: kept by the Nosé–Hoover flow (equal to energy() for Langevin).
  double extended_energy(const state& x) const {
    return energy(x) + x.bath.translation.energy(x.bath.translation_state) + x.bath.rotation.energy(x.bath.rotation_state);
  }

 private:
  // the chains of this state's size, built once (a state handed from another system keeps its own chains' values)
  void ready_chains(state& x) const {
    const double dt = translational_dof(x), dr = rotational_dof(x);
    if (x.bath.translation.dof() == dt && x.bath.rotation.dof() == dr && x.bath.translation.kT() == p_.kT) return;
    x.bath.translation = nose_hoover_chain(dt, p_.kT, p_.tau, p_.chain_length, p_.chain_order, p_.chain_iterations);
    x.bath.rotation = nose_hoover_chain(dr, p_.kT, p_.tau, p_.chain_length, p_.chain_order, p_.chain_iterations);
    if (x.bath.translation_state.v.size() != static_cast<std::size_t>(p_.chain_length)) x.bath.translation_state = x.bath.translation.rest();
    if (x.bath.rotation_state.v.size() != static_cast<std::size_t>(p_.chain_length)) x.bath.rotation_state = x.bath.rotation.rest();
  }

  Bodies bodies_;
  thermostat_parameters p_;
};

}  // namespace rotlie::models
