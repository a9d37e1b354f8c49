#pragma once
// The water molecule of van Zon & Schofield section V.A–B, in LAMMPS `real` units (real_units.hpp).
//
// Moments: Eisenberg & Kauzmann's 1.0220, 1.9187, 2.9376 × 10⁻⁴⁰ g cm² (the set Laskar & Vaillant
// use for water, section 4.3, as the ratios 10220 : 19187 : 29376). van Zon & Schofield only say
// "the moments of inertia of a water molecule"; the E&K set is a real molecule's (not a rigid
// model's, which is exactly planar, I1 + I2 = I3) and is the body the dedicated rotors are solved
// for, so SIER2/N2:BAC:2 and the others run on the body they were made for. Converted exactly:
// 10⁻⁴⁰ g cm² = 10⁻²⁴ g Å² = 0.602214076 g/mol·Å² (N_A = 6.02214076e23, exact since 2019), so the
// decimals below are exact products. Axes: I1 < I2 < I3 are the in-plane axis perpendicular to
// C2, the C2 (dipole) axis, and the normal to the plane.
#include <string>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models::water {

/// The principal moments, g/mol·Å², as exact decimal text (read into the scalar in use).
inline constexpr const char* moments_text[3] = {"0.615462785672", "1.1554681476212", "1.7690640696576"};
/// The moments as a body name ("I1,I2,I3") for the name resolution of a rotor table.
inline std::string body_text() { return std::string(moments_text[0]) + "," + moments_text[1] + "," + moments_text[2]; }
/// The same body as an exact ratio (for a table's `inertia` line; equal up to a common factor).
inline constexpr const char* moments_ratio = "10220,19187,29376";
/// H₂O, g/mol.
inline constexpr const char* mass_text = "18.01528";
/// The C2 axis, along which the dipole lies: body axis 2 of 3 (index 1), the intermediate moment.
inline constexpr int c2_axis = 1;
/// vZS section V.B: the molecule's dipole (debye) and the field (MV/m, along lab z).
inline constexpr double dipole_debye = 1.84;
inline constexpr double field_mv_per_m = 2.7;
/// vZS section V: the temperature of the canonical initial conditions (K).
inline constexpr double temperature = 297;

template <class T>
vec3<T> moments() {
  return {parse_scalar<T>(moments_text[0]), parse_scalar<T>(moments_text[1]), parse_scalar<T>(moments_text[2])};
}

template <class T>
T mass() {
  return parse_scalar<T>(mass_text);
}

}  // namespace rotlie::models::water
