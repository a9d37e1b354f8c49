#pragma once
// Canonical initial conditions at temperature T_K for one rigid body (vZS section V: "drawn from a
// canonical distribution at 297 K"): body-frame angular momentum G_i Gaussian with variance
// I_i k_B T / mvv2e (equipartition, ⟨G_i²/2I_i⟩·mvv2e = k_B T/2), momentum p_i Gaussian with variance
// m k_B T / mvv2e, centre at the origin, and an attitude uniform on SO(3) (a unit quaternion from four
// normals: the normal distribution in R⁴ is isotropic). The numbers are drawn in double from
// seeded_random, so that a seed gives the same initial states in every scalar; the quaternion is
// normalised and turned into Q in the run's scalar, so that Q is orthogonal to that scalar's precision.
#include <cmath>
#include <cstdint>

#include "rotlie/models/real_units.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/seeded_random.hpp"

namespace rotlie::models {

/// The rotation of the unit quaternion (w, x, y, z), normalised in T first.
template <class T>
mat3<T> rotation_of_quaternion(T w, T x, T y, T z) {
  using std::sqrt;
  const T n = sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  mat3<T> Q;
  Q(0, 0) = 1 - 2 * (y * y + z * z), Q(0, 1) = 2 * (x * y - w * z), Q(0, 2) = 2 * (x * z + w * y);
  Q(1, 0) = 2 * (x * y + w * z), Q(1, 1) = 1 - 2 * (x * x + z * z), Q(1, 2) = 2 * (y * z - w * x);
  Q(2, 0) = 2 * (x * z - w * y), Q(2, 1) = 2 * (y * z + w * x), Q(2, 2) = 1 - 2 * (x * x + y * y);
  return Q;
}

/// Run `run` of the canonical ensemble with seed `seed`, for a body of mass m (g/mol) and moments
/// I (g/mol·Å²) at temperature_K. The draws depend on (seed, run) and on the moments and mass in double.
template <class T>
rigid_body_state<T> canonical_state(std::uint64_t seed, std::uint64_t run, const T& mass, const vec3<T>& I,
                                    double temperature_K) {
  seeded_random rng(seed, run);
  const double kT = real_units::boltz<double>() * temperature_K / real_units::mvv2e<double>();  // g/mol·Å²/fs²
  rigid_body_state<T> b;
  for (std::size_t i = 0; i < 3; ++i) b.rot.G[i] = T(std::sqrt(static_cast<double>(I[i]) * kT) * rng.normal());
  for (std::size_t i = 0; i < 3; ++i) b.p[i] = T(std::sqrt(static_cast<double>(mass) * kT) * rng.normal());
  const double w = rng.normal(), x = rng.normal(), y = rng.normal(), z = rng.normal();
  b.rot.Q = rotation_of_quaternion<T>(T(w), T(x), T(y), T(z));
  return b;
}

}  // namespace rotlie::models
