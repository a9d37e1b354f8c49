#pragma once
// The integrators for rigid bodies under torques, each a TV table and a free rotor (a listed
// closed-form rotor or a table rotor), composed for the scene's bodies. The names users type (SIER2,
// MRDL, SIER4/X, …) and what each means are the method registry's (runs/methods.hpp); this header takes
// the parts it resolves them into.
// MRDL's rotor: the planar rotations of Dullweber, Leimkuhler & McLachlan (1997) in their order,
// axes 1, 2, 3, 2, 1 with the full step on axis 3 (ABCBA2, permutation ABC); for water
// (I1 < I2 < I3) the full step falls on the slowest axis. This is the order with which vZS's τ and
// Table I are reproduced (the report's vzs section), and it is also the map of LAMMPS's NO_SQUISH
// (fix rigid/nve, rigid/nve/small): LAMMPS numbers the principal axes by decreasing moment, so its
// sequence 3, 2, 1, 2, 3 with the full step on its axis 1 is, in rotlie's increasing-moment
// numbering, 1, 2, 3, 2, 1 with the full step on the largest moment (checked against a LAMMPS run
// in liquid_water_lammps_test). MRDL-reversed is MRDL with the axis order reversed, 3, 2, 1, 2, 3
// with the full step on the smallest moment (ABCBA2:CBA): also 2nd order, but for water the full
// step falls on the fastest axis and its leapfrog remainder is larger. Both are tested against the
// NO_SQUISH quaternion form in their own axis order (no_squish.hpp).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/closed_form_rotors.hpp"
#include "rotlie/models/composition.hpp"
#include "rotlie/models/table_rotor.hpp"
#include "rotlie/models/thermostats/thermostatted_bodies.hpp"
#include "rotlie/models/torqued_rigid_bodies.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::models {

struct md_integrator {
  std::string name;          ///< the name it was given by (shown in output only)
  std::string tv_table;      ///< a reference TV table: Strang-TV, PEFRL-TV, KahanLi6-TV
  std::string rotor = "exact";  ///< a closed-form rotor's name (closed_form_rotors.hpp), or empty: rotor_table
  std::string rotor_table;   ///< the free-rotation table's name (an empty rotor only)
  int f = 1;                 ///< force evaluations per step
  /// at a temperature: where the thermostat goes in the TV table (with_thermostatted_integrator); none: NVE
  std::optional<schemes::thermostat_placement> thermostat;

  bool table_rotor() const { return rotor.empty(); }
};

/// MRDL's free rotor, axes 1-2-3-2-1 (DLM's order and LAMMPS's map), and MRDL-reversed's, 3-2-1-2-3
/// (see the header comment).
inline constexpr const char* mrdl_rotor_table = "ABCBA2:ABC";
inline constexpr const char* mrdl_reversed_rotor_table = "ABCBA2:CBA";

/// An integrator from its parts, as the method registry (runs/methods.hpp) resolves a name into them:
/// the TV table and the rotor (a listed rotor's name, else a table's); f from the TV table unless given.
inline md_integrator md_integrator_of(std::string name, std::string tv_table, const std::string& rotor, int f = 0) {
  if (f == 0) f = schemes::force_evaluations(*schemes::reference_scheme(tv_table));
  if (is_closed_form_rotor(rotor)) return {std::move(name), std::move(tv_table), rotor, "", f, std::nullopt};
  return {std::move(name), std::move(tv_table), "", rotor, f, std::nullopt};
}

/// One body type as a scene states it; the rotor comes from the integrator. For a table rotor,
/// rotor_table is the table resolved for this body, or nullptr to look the name up among the
/// reference schemes.
template <class T>
struct body_kind {
  T mass;
  vec3<T> moments;
  const schemes::scheme_table* rotor_table = nullptr;
};

/// The system of bodies under `potential` with the integrator's rotor for each type, handed to
/// visit_system(torqued_rigid_bodies<T, Potential, Rotor>) (every branch must return the same type).
/// Throws std::invalid_argument when a rotor table cannot be found or does not load.
template <class T, class Potential, class Visitor>
auto with_md_system(const md_integrator& spec, const std::vector<body_kind<T>>& kinds, const Potential& potential,
                    const unit_system<T>& units, Visitor&& visit_system) {
  static_assert(torque_potential<Potential, T>, "the scene's potential must be a torque_potential (scene_contracts.hpp)");
  // one rotor per body type, all of one kind
  auto run = [&](auto rotor_of) {
    using rotor = decltype(rotor_of(kinds.front()));
    using system = torqued_rigid_bodies<T, Potential, rotor>;
    static_assert(rigid_body_system<system>);
    static_assert(clocked_system<system>, "the engine must write the clock of a body under torques (step_clock.hpp)");
    std::vector<body_type<T, rotor>> types;
    types.reserve(kinds.size());
    for (const auto& k : kinds) types.push_back({k.mass, k.moments, rotor_of(k)});
    return visit_system(system(std::move(types), potential, units));
  };
  if (!spec.table_rotor())
    return with_closed_form_rotor<T>(spec.rotor, [&](auto rotor) {
      using R = typename decltype(rotor)::type;
      return run([](const body_kind<T>& k) { return R(k.moments); });
    });
  return run([&](const body_kind<T>& k) {
    std::optional<schemes::scheme_table> table;
    if (k.rotor_table)
      table = *k.rotor_table;
    else
      table = schemes::reference_scheme(spec.rotor_table);
    if (!table)
      throw std::invalid_argument("integrator " + schemes::printable_text(spec.name) + ": '" + schemes::printable_text(spec.rotor_table) +
                                  "' is not a reference scheme (a dedicated table must be solved for the body first)");
    return table_rotor<T>(*table, k.moments);
  });
}

/// The composition of an integrator for bodies of several types under `potential`, in `units`, handed
/// to visit(const composition<torqued_rigid_bodies<T, Potential, Rotor>>&) (every branch must return
/// the same type). Throws std::invalid_argument when a table cannot be found or does not load.
template <class T, class Potential, class Visitor>
auto with_md_integrator(const md_integrator& spec, const std::vector<body_kind<T>>& kinds, const Potential& potential,
                        const unit_system<T>& units, Visitor&& visit) {
  const auto tv = *schemes::reference_scheme(spec.tv_table);
  return with_md_system<T>(spec, kinds, potential, units, [&](auto system) { return visit(composition<decltype(system)>(tv, std::move(system))); });
}

/// The same integrator at a temperature: its TV table with the thermostat at `placement`
/// (schemes::thermostatted_table: BAOAB, OBABO, NHC), visit(const composition<thermostatted_bodies<…>>&).
/// Throws std::invalid_argument as with_md_integrator, and for parameters the thermostat cannot take.
template <class Potential, class Visitor>
auto with_thermostatted_integrator(const md_integrator& spec, schemes::thermostat_placement placement, const thermostat_parameters& bath,
                                   const std::vector<body_kind<double>>& kinds, const Potential& potential,
                                   const unit_system<double>& units, Visitor&& visit) {
  const auto table = schemes::thermostatted_table(*schemes::reference_scheme(spec.tv_table), placement);
  return with_md_system<double>(spec, kinds, potential, units, [&](auto system) {
    using bodies = thermostatted_bodies<decltype(system)>;
    return visit(composition<bodies>(table, bodies(std::move(system), bath)));
  });
}

/// The same for one body type of mass m and moments I in real units (the scenes of van Zon & Schofield).
template <class T, class Potential, class Visitor>
auto with_md_integrator(const md_integrator& spec, const schemes::scheme_table* rotor_table, const T& mass, const vec3<T>& I,
                        const Potential& potential, Visitor&& visit) {
  return with_md_integrator<T>(spec, std::vector<body_kind<T>>{{mass, I, rotor_table}}, potential, unit_system<T>::real(),
                               std::forward<Visitor>(visit));
}

}  // namespace rotlie::models
