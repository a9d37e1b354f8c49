#pragma once
// The rigid TIP3P water model of Jorgensen, Chandrasekhar, Madura, Impey & Klein (J. Chem. Phys.
// 79, 926, 1983) in LAMMPS real units: three sites O, H, H with r_OH = 0.9572 Å, ∠HOH = 104.52°,
// charges q_H = +0.417 e, q_O = −0.834 e, Lennard-Jones on O–O only from the paper's A = 582.0e3
// kcal Å¹²/mol and B = 595.0 kcal Å⁶/mol (σ = (A/B)^(1/6), ε = B²/4A).
//
// Why TIP3P: van Zon & Schofield cite the paper without saying which model; TIP3P's three sites
// all carry mass and charge, so LAMMPS's rigid-body fixes can integrate the very same body
// (TIP4P's massless M site cannot be a LAMMPS rigid-body atom without changing the inertia), and
// the side-by-side comparison stays one to one.
//
// Body frame: origin at the centre of mass, principal axes in the order of increasing moment:
// axis 0 along H–H (smallest), axis 1 the C2 bisector pointing from O towards the H's
// (intermediate), axis 2 normal to the plane (largest, I₂ = I₀ + I₁: a planar body).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

template <class T>
struct water_model {
  static constexpr int sites = 3;  ///< O, H, H
  std::string name = "TIP3P";
  T mass_O, mass_H, mass;          ///< g/mol
  std::array<T, sites> charge;     ///< e
  T sigma, epsilon;                ///< O–O Lennard-Jones (Å, kcal/mol)
  std::array<vec3<T>, sites> site; ///< body-frame site positions (Å) about the centre of mass
  vec3<T> moments;                 ///< principal moments (g/mol·Å²)
  T site_radius;                   ///< the largest site distance from the centre of mass (Å)
};

/// TIP3P's principal moments (g/mol·Å², body axes 0, 1, 2) as decimal text for the symbolic side,
/// which solves a dedicated rotor for these exact rationals: the moments of tip3p() below to 18
/// significant digits (computed at 40 digits from the same geometry), I₂ written as the exact sum
/// of the other two so that the solved body is planar exactly, as the molecule is.
inline constexpr const char* tip3p_moments_text[3] = {"0.614537057924512665", "1.15504641980048714", "1.769583477724999805"};

/// The same as one I1,I2,I3 text (the form --inertia takes).
inline std::string tip3p_body_text() {
  return std::string(tip3p_moments_text[0]) + "," + tip3p_moments_text[1] + "," + tip3p_moments_text[2];
}

/// TIP3P with every number read from its published decimal text into T.
template <class T>
water_model<T> tip3p() {
  using std::cos;
  using std::pow;
  using std::sin;
  using std::sqrt;
  water_model<T> w;
  w.mass_O = parse_scalar<T>("15.9994");
  w.mass_H = parse_scalar<T>("1.00794");
  w.mass = w.mass_O + 2 * w.mass_H;
  const T qH = parse_scalar<T>("0.417");
  w.charge = {-2 * qH, qH, qH};
  const T A = parse_scalar<T>("582000"), B = parse_scalar<T>("595");
  w.sigma = pow(A / B, T(1) / 6);
  w.epsilon = B * B / (4 * A);
  const T r = parse_scalar<T>("0.9572");
  const T pi = T(4) * atan(T(1));
  const T half_angle = parse_scalar<T>("104.52") / 2 * pi / 180;
  const T x = r * sin(half_angle), y = r * cos(half_angle);
  const T y_com = 2 * w.mass_H * y / w.mass;  // the centre of mass on the bisector, from O
  w.site = {vec3<T>{T(0), -y_com, T(0)}, vec3<T>{-x, y - y_com, T(0)}, vec3<T>{x, y - y_com, T(0)}};
  const std::array<T, 3> m{w.mass_O, w.mass_H, w.mass_H};
  w.moments = {};
  for (int a = 0; a < 3; ++a) {
    w.moments[0] += m[a] * w.site[a][1] * w.site[a][1];
    w.moments[1] += m[a] * w.site[a][0] * w.site[a][0];
  }
  w.moments[2] = w.moments[0] + w.moments[1];
  w.site_radius = 0;
  for (const auto& s : w.site) w.site_radius = std::max(w.site_radius, T(sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2])));
  return w;
}

/// The side of the cubic box holding n molecules of mass m (g/mol) at density rho (g/cm³), Å.
template <class T>
T cubic_box_side(long n, const T& molar_mass, const T& rho_g_per_cm3) {
  using std::cbrt;
  const T avogadro = parse_scalar<T>("6.02214076e23");
  const T volume_cm3 = T(n) * molar_mass / avogadro / rho_g_per_cm3;
  return cbrt(volume_cm3) * parse_scalar<T>("1e8");
}

}  // namespace rotlie::models
