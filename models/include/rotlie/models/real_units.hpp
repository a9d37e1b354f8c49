#pragma once
// LAMMPS `units real` (Å, fs, g/mol, kcal/mol, e, K) with LAMMPS's own constants, so that runs
// compare one to one with LAMMPS. Each constant is read from its decimal text into the scalar in
// use (no double rounding in a float128 run).
//   momentum p: g/mol·Å/fs; body angular momentum G: g/mol·Å²/fs; moments: g/mol·Å²
//   kinetic energy (kcal/mol) = mvv2e · (p²/2m + Σ G_i²/2I_i)
//   kicks: p += c h ftm2v F (F in kcal/mol/Å), G += c h ftm2v Qᵀτ (lab torque τ in kcal/mol)
#include "rotlie/models/composition.hpp"

namespace rotlie::models::real_units {

/// (g/mol·Å²/fs²) → kcal/mol: the square of 48.88821291.
template <class T>
T mvv2e() {
  const T v = parse_scalar<T>("48.88821291");
  return v * v;
}

/// kcal/mol/Å per (g/mol) → Å/fs²: 1/mvv2e.
template <class T>
T ftm2v() {
  return T(1) / mvv2e<T>();
}

// LAMMPS's constants of `units real`, each read from its decimal text.
template <class T> T boltz() { return parse_scalar<T>("0.0019872067"); }  ///< Boltzmann's constant, kcal/mol/K
template <class T> T qqr2e() { return parse_scalar<T>("332.06371"); }     ///< Coulomb's constant, kcal/mol·Å/e²
template <class T> T qe2f() { return parse_scalar<T>("23.060549"); }      ///< e·V/Å → kcal/mol/Å (so e·V → kcal/mol)
template <class T> T debye() { return parse_scalar<T>("0.20819434"); }    ///< one debye in e·Å

}  // namespace rotlie::models::real_units
