#pragma once
// Scene "dipole in a field" (vZS section V.B, Table I): one water molecule whose dipole (1.84 D)
// lies along its C2 axis, in a uniform field of 2.7 MV/m along lab z; canonical initial conditions
// at 297 K. The field exerts a torque only (no force), perpendicular to z, so L_z and H are the
// conserved quantities the table measures. Units: 1 D = 0.20819434 e·Å; 1 MV/m = 10⁻⁴ V/Å.
#include <cstdint>
#include <string>

#include "rotlie/models/scenes/canonical_state.hpp"
#include "rotlie/models/scenes/dipole_in_field.hpp"
#include "rotlie/models/scenes/water.hpp"
#include "rotlie/models/unit_system.hpp"

namespace rotlie::models {

template <class T>
struct dipole_field {
  /// The dipole (debye) and field (MV/m) as decimal text, read at the precision of T. Throws
  /// std::invalid_argument (from dipole_in_field) for a value that is not finite.
  explicit dipole_field(const std::string& dipole_debye = "1.84", const std::string& field_mv_per_m = "2.7")
      : potential(parse_scalar<T>(dipole_debye) * real_units::debye<T>(), water::c2_axis,
                  vec3<T>{T(0), T(0), parse_scalar<T>(field_mv_per_m) / T(10000)}) {}

  T mass = water::mass<T>();
  vec3<T> moments = water::moments<T>();
  unit_system<T> units = unit_system<T>::real();
  dipole_in_field<T> potential;

  rigid_bodies_state<T> initial(std::uint64_t seed, std::uint64_t run) const {
    rigid_bodies_state<T> s;
    s.bodies.push_back(canonical_state<T>(seed, run, mass, moments, water::temperature));
    return s;
  }
};

}  // namespace rotlie::models
