#pragma once
// What a scene hands the integrators, as concepts (in the style of splitting_system, composition.hpp):
//   torque_potential<P, T>   V, the lab forces and the lab torques of a configuration at a time t
//   free_rotor<R, T>         the free rotation of one body type over a time (exact flow or a table)
//   rigid_body_system<S>     a splitting system of rigid bodies under torques, with its energies
//   run_observer<O, S, T>    called as obs(k, t, state) after step k; returns void, or bool (false stops)
// A potential may ignore time: evaluate(bodies, force, torque) is then the whole contract, and
// potential_at() calls it without t, so that today's potentials run unchanged.
#include <concepts>
#include <type_traits>
#include <vector>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

/// V(x, t): fills the lab forces and torques (vectors sized to the bodies) and returns V.
template <class P, class T>
concept time_dependent_potential = requires(const P& p, const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force,
                                            std::vector<vec3<T>>& torque, const T& t) {
  { p.evaluate(bodies, force, torque, t) } -> std::convertible_to<T>;
};

/// V(x): the same without a time (every potential of the van Zon–Schofield scenes).
template <class P, class T>
concept time_independent_potential = requires(const P& p, const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force,
                                              std::vector<vec3<T>>& torque) {
  { p.evaluate(bodies, force, torque) } -> std::convertible_to<T>;
};

/// A potential of one of the two kinds; acts() is false for V = 0 (kicks skipped, nothing evaluated).
template <class P, class T>
concept torque_potential = (time_dependent_potential<P, T> || time_independent_potential<P, T>) && requires(const P& p) {
  { p.acts() } -> std::convertible_to<bool>;
};

/// V at time t, whichever kind the potential is.
template <class T, torque_potential<T> P>
T potential_at(const P& p, const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque,
               const T& t) {
  if constexpr (time_dependent_potential<P, T>)
    return p.evaluate(bodies, force, torque, t);
  else
    return p.evaluate(bodies, force, torque);
}

/// The free rotation of one body type for a time t (exact_free_rotation, table_rotor, sej4_rotor),
/// its moments bound at construction.
template <class R, class T>
concept free_rotor = requires(const R& r, body_state<T>& s, const T& t) {
  r.advance(s, t);
  { r.moments() } -> std::convertible_to<const vec3<T>&>;
};

/// A splitting system of rigid bodies whose states carry forces, with the energies the experiments
/// measure (torqued_rigid_bodies).
template <class S>
concept rigid_body_system = splitting_system<S> && std::same_as<typename S::state, rigid_bodies_state<typename S::scalar>> &&
                            requires(const S& sys, typename S::state& x, const typename S::state& cx) {
                              sys.ensure_forces(x);
                              { sys.kinetic_energy(cx) } -> std::convertible_to<typename S::scalar>;
                              { sys.potential_energy(cx) } -> std::convertible_to<typename S::scalar>;
                              { sys.energy(cx) } -> std::convertible_to<typename S::scalar>;
                            };

/// Called as obs(k, t, x) after step k (integrate.hpp); void, or bool where false stops the run.
template <class O, class State, class T>
concept run_observer = requires(O& obs, long k, const T& t, const State& x) {
  obs(k, t, x);
} && (std::is_void_v<std::invoke_result_t<O&, long, const T&, const State&>> ||
      std::same_as<std::invoke_result_t<O&, long, const T&, const State&>, bool>);

}  // namespace rotlie::models
