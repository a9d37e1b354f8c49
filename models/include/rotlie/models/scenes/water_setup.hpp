#pragma once
// An initial liquid without outside tools: molecules on a simple cubic lattice filling the box,
// uniformly random orientations, Maxwell–Boltzmann momenta at temperature T with zero total
// momentum; then a short equilibration under a Berendsen thermostat (the only place a thermostat
// is used: production runs are NVE).
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>

#include "rotlie/models/real_units.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/water_model.hpp"

namespace rotlie::models {

/// The rotation of a unit quaternion (w, x, y, z).
template <class T>
mat3<T> quaternion_rotation(const T& w, const T& x, const T& y, const T& z) {
  mat3<T> r;
  r(0, 0) = 1 - 2 * (y * y + z * z);
  r(0, 1) = 2 * (x * y - w * z);
  r(0, 2) = 2 * (x * z + w * y);
  r(1, 0) = 2 * (x * y + w * z);
  r(1, 1) = 1 - 2 * (x * x + z * z);
  r(1, 2) = 2 * (y * z - w * x);
  r(2, 0) = 2 * (x * z - w * y);
  r(2, 1) = 2 * (y * z + w * x);
  r(2, 2) = 1 - 2 * (x * x + y * y);
  return r;
}

/// n molecules on a simple cubic lattice in a box of side L, random orientations (uniform on
/// SO(3): a normalised 4-vector of Gaussians), thermal momenta at `kelvin` with zero total momentum.
template <class T>
rigid_bodies_state<T> lattice_water(const water_model<T>& model, long n, const T& L, const T& kelvin, std::uint64_t seed) {
  using std::cbrt;
  using std::ceil;
  using std::sqrt;
  if (n < 1) throw std::invalid_argument("at least one molecule");
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const long side = static_cast<long>(ceil(cbrt(static_cast<double>(n)) - 1e-9));
  const T a = L / T(side);
  const T kT = real_units::boltz<T>() * kelvin / real_units::mvv2e<T>();  // g/mol·Å²/fs²
  rigid_bodies_state<T> s;
  s.bodies.resize(static_cast<std::size_t>(n));
  vec3<T> total{};
  for (long k = 0; k < n; ++k) {
    auto& b = s.bodies[static_cast<std::size_t>(k)];
    b.q = {a * (T(k / (side * side)) + T(0.5)), a * (T((k / side) % side) + T(0.5)), a * (T(k % side) + T(0.5))};
    T qv[4];
    T norm = 0;
    for (auto& c : qv) {
      c = T(gauss(rng));
      norm += c * c;
    }
    norm = sqrt(norm);
    b.rot.Q = quaternion_rotation(qv[0] / norm, qv[1] / norm, qv[2] / norm, qv[3] / norm);
    for (int d = 0; d < 3; ++d) {
      b.p[d] = T(gauss(rng)) * sqrt(model.mass * kT);
      b.rot.G[d] = T(gauss(rng)) * sqrt(model.moments[d] * kT);
      total[d] += b.p[d];
    }
  }
  for (auto& b : s.bodies)
    for (int d = 0; d < 3; ++d) b.p[d] -= total[d] / T(n);
  return s;
}

/// Temperature from the kinetic energy (kcal/mol) of n rigid molecules with zero total momentum:
/// 6n − 3 degrees of freedom.
template <class T>
T temperature_of(const T& kinetic, long n) {
  return 2 * kinetic / (T(6 * n - 3) * real_units::boltz<T>());
}

/// Berendsen's weak coupling for one step h: all momenta scaled by λ, λ² = 1 + (h/τ)(T₀/T − 1).
template <class T>
void berendsen_scale(rigid_bodies_state<T>& s, const T& current, const T& target, const T& h, const T& tau) {
  using std::sqrt;
  const T lambda2 = 1 + h / tau * (target / current - 1);
  const T lambda = sqrt(lambda2 > T(0.25) ? lambda2 : T(0.25));
  for (auto& b : s.bodies)
    for (int d = 0; d < 3; ++d) {
      b.p[d] *= lambda;
      b.rot.G[d] *= lambda;
    }
}

/// `steps` steps of `method` with a Berendsen thermostat after each (equilibration only).
/// progress(k) is called every `every` steps and may be empty.
template <class Composition, class Progress>
void equilibrate(const Composition& method, typename Composition::state& s, const typename Composition::scalar& h, long steps,
                 const typename Composition::scalar& kelvin, const typename Composition::scalar& tau, Progress&& progress, long every = 100,
                 const std::function<void()>& poll = {}) {
  const auto& sys = method.system();
  const long n = static_cast<long>(s.bodies.size());
  for (long k = 1; k <= steps; ++k) {
    if (poll) poll();  // every step, apart from progress: its potential energy costs a force evaluation
    method.step(s, h);
    berendsen_scale(s, temperature_of(sys.kinetic_energy(s), n), kelvin, h, tau);
    if (k % every == 0) progress(k, temperature_of(sys.kinetic_energy(s), n), sys.potential_energy(s) / typename Composition::scalar(n));
  }
}

}  // namespace rotlie::models
