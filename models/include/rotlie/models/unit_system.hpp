#pragma once
// Units as data of a scene: the names of its units and the two factors the equations of motion of
// rigid bodies need,
//   kicks:          p += c h ftm2v F,  G += c h ftm2v Qᵀτ   (force·time/mass → velocity)
//   kinetic energy: mvv2e · (p²/2m + Σ G_i²/2I_i)           (mass·velocity² → energy)
// LAMMPS `units real` is one instance (real_units.hpp), natural units with every factor 1 another
// (a spin–orbit scene with G M = 1). A system multiplies by these values exactly where it used to
// multiply by the real-unit constants, so that real-unit runs keep every bit.
#include "rotlie/models/real_units.hpp"

namespace rotlie::models {

template <class T>
struct unit_system {
  const char* name = "natural";
  const char* time = "1";
  const char* length = "1";
  const char* mass = "1";
  const char* energy = "1";
  T ftm2v = T(1);  ///< force·time/mass → velocity
  T mvv2e = T(1);  ///< mass·velocity² → energy

  /// LAMMPS `units real`: Å, fs, g/mol, kcal/mol.
  static unit_system real() { return {"real", "fs", "Å", "g/mol", "kcal/mol", real_units::ftm2v<T>(), real_units::mvv2e<T>()}; }

  /// Every factor 1: time, length and mass in the scene's own scale (G M = 1 for an orbit).
  static unit_system natural() { return {}; }
};

}  // namespace rotlie::models
