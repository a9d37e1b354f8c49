#pragma once
// Shared pieces of the torqued-body tests: a water-like body in LAMMPS real units, the dipole in a
// strong field along z (so that the kicks matter as much as the free flight), a few fixed initial
// conditions of thermal size, distances between states, and runs of a named integrator.
#include <cmath>
#include <string>
#include <vector>

#include "rotlie/models/integrate.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/real_units.hpp"
#include "rotlie/models/scenes/dipole_in_field.hpp"
#include "rotlie/models/scenes/zero_potential.hpp"
#include "md_splittings.hpp"

namespace rotlie::test {

/// Water: mass 2·1.00794 + 15.9994 g/mol; moments E&K 1.0220, 1.9187, 2.9376 × 10⁻⁴⁰ g cm²
/// (10⁻⁴⁰ g cm² = 0.602214076 g/mol·Å²).
template <class T>
T water_mass() {
  return models::parse_scalar<T>("18.01528");
}
template <class T>
models::vec3<T> water_moments_real() {
  const T unit = models::parse_scalar<T>("0.0000602214076");
  return {T(10220) * unit, T(19187) * unit, T(29376) * unit};
}

/// 1.84 D along the C2 axis (body axis 1, the intermediate moment) in a field E along z (V/Å).
template <class T>
models::dipole_in_field<T> dipole_scene(const T& field) {
  return models::dipole_in_field<T>(T(184) / 100 * models::real_units::debye<T>(), 1, {T(0), T(0), field});
}

/// A strong field, 0.5 V/Å: μE ≈ 4.4 kcal/mol against kT ≈ 0.59 kcal/mol at 297 K.
template <class T>
T strong_field() {
  return T(1) / 2;
}

/// `n` bodies with body momenta of thermal size (≈ √(I kT / mvv2e) ≈ 0.01–0.02 g/mol·Å²/fs) in
/// different directions and tilted attitudes, some translation.
template <class T>
models::rigid_bodies_state<T> thermal_bodies(int n) {
  models::rigid_bodies_state<T> s;
  const T g[4][3] = {{T(0.011), T(0.019), T(-0.013)},
                     {T(-0.007), T(0.004), T(0.025)},
                     {T(0.016), T(-0.012), T(0.009)},
                     {T(0.003), T(0.021), T(0.017)}};
  for (int k = 0; k < n; ++k) {
    models::rigid_body_state<T> b;
    b.q = {T(3 * k), T(0), T(0)};
    b.p = {T(0.05), T(-0.02 * k), T(0.01)};
    b.rot.G = {g[k % 4][0], g[k % 4][1], g[k % 4][2]};
    const models::vec3<T> axis{T(1) / 3, T(2) / 3, T(2) / 3};  // unit
    b.rot.Q = models::rotation(axis, T(0.4) + T(0.7) * T(k));
    s.bodies.push_back(b);
  }
  return s;
}

/// Σ over bodies of ‖Q − Q'‖_F + ‖G − G'‖ / 0.02 + ‖q − q'‖ (attitude, momentum on its thermal scale,
/// position in Å).
template <class T, class U>
double state_distance(const models::rigid_bodies_state<T>& a, const models::rigid_bodies_state<U>& b) {
  double s = 0;
  for (std::size_t n = 0; n < a.bodies.size(); ++n) {
    double dq = 0, dg = 0, dx = 0;
    for (std::size_t i = 0; i < 9; ++i) {
      const double d = static_cast<double>(a.bodies[n].rot.Q.a[i]) - static_cast<double>(b.bodies[n].rot.Q.a[i]);
      dq += d * d;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      const double d = static_cast<double>(a.bodies[n].rot.G[i]) - static_cast<double>(b.bodies[n].rot.G[i]);
      dg += d * d;
      const double e = static_cast<double>(a.bodies[n].q[i]) - static_cast<double>(b.bodies[n].q[i]);
      dx += e * e;
    }
    s += std::sqrt(dq) + std::sqrt(dg) / 0.02 + std::sqrt(dx);
  }
  return s;
}

/// `steps` steps of size h of integrator `name` under `potential` from s.
template <class T, class Potential>
models::rigid_bodies_state<T> run(const std::string& name, const Potential& potential, models::rigid_bodies_state<T> s, const T& h,
                                  long steps) {
  const auto spec = rotlie::test::splitting(name);
  models::with_md_integrator<T>(spec, nullptr, water_mass<T>(), water_moments_real<T>(), potential, [&](const auto& method) {
    models::integrate(method, s, h, steps);
    return 0;
  });
  return s;
}

/// Least-squares slope of log y against log x.
inline double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += std::log(x[i]);
    my += std::log(y[i]);
  }
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

}  // namespace rotlie::test
