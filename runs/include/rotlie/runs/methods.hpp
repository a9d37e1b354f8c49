#pragma once
// The integrators a user can name, each family one row of data (method_list.cpp), and the one parser
// of their names: md's, spin's and binary's --integrator, Python's integrator=, LAMMPS's rotor keyword
// and fix styles, and the studies resolve through it; every list of names shown to a user is generated
// from the rows. The grammar:
//   FAMILY[/ROTOR]        a splitting; ROTOR (families that take one): a listed closed-form rotor
//                         (models/closed_form_rotors.hpp), a reference scheme with its permutation,
//                         SCHEME:PERM:LABEL solved for each body's moments, or a scheme-table file
//   FAMILY[/ROTOR]-BAOAB, -OBABO, -NHC
//                         md's splittings at a temperature: the TV table with a thermostat's stages
//                         (schemes/thermostat_tables.hpp; models::md_integrator::thermostat)
//   odeint-METHOD[:TOL]   Boost.Odeint's adaptive methods, TOL their absolute and relative tolerance
// What comes out is typed (models::md_integrator, scheme tables solved for the bodies): models/ never
// reads the name's text.
#include <optional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/odeint_checkpoints.hpp"
#include "rotlie/models/small_matrix.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

/// What a method steps: md's rigid bodies under torques (its scenes), spin's body on a fixed Kepler
/// orbit, binary's two bodies with their mutual orbit.
enum class method_system { md, spin, binary };

/// How a family steps.
enum class method_kind {
  tv_splitting,      ///< a TV composition of T (free flight, the free rotor) and V (kicks)
  kepler_splitting,  ///< the same composition of H_Kepler + T_rot and U − U₀ (Wisdom–Holman; binary)
  rk4,               ///< the classical Runge–Kutta step of the equations of motion (GUBAS's anchor)
  lgvi,              ///< the Lie-group variational integrator (GUBAS's anchor)
  adaptive           ///< a Boost.Odeint controlled stepper
};

/// One family of integrators.
struct method_family {
  std::string name;                   ///< SIER2, KEPLER4, RK4, odeint-rkf78, …
  method_kind kind = method_kind::tv_splitting;
  int order = 2;                      ///< of the composition (a rotor of lower order lowers it)
  std::string tv_table;               ///< splittings: the composition's TV table (schemes::reference_scheme)
  std::string rotor;                  ///< splittings: the free rotor when none is named (a listed rotor or a table)
  bool takes_rotor = false;           ///< FAMILY/ROTOR
  models::odeint_method ode = models::odeint_method::rkf78;  ///< adaptive
  std::vector<method_system> systems;
  std::string description;            ///< one line
  bool lammps_style = false;          ///< a LAMMPS fix style rigid/NAME/small (a TV splitting of md with a rotor keyword)

  bool steps(method_system s) const;
  /// Force (torque) evaluations per step: the TV table's kicks less first-same-as-last; RK4 4, LGVI 1;
  /// 0 for an adaptive method (it varies).
  int force_evaluations() const;
  /// The names it is typed as: "SIER2" and "SIER2/X", or "odeint-rkf78[:TOL]".
  std::vector<std::string> forms() const;
};

/// The families, in the order every list shows them.
const std::vector<method_family>& method_families();

/// A system's name as the front ends say it ("md", "spin", "binary") and back.
std::string system_name(method_system s);
std::optional<method_system> system_named(const std::string& name);
/// Every system, in order.
const std::vector<method_system>& method_systems();

/// The names that system takes, e.g. "SIER2, SIER4, …, SIER2/X, …, odeint-rkf78[:TOL] (X a rotor: exact,
/// sej4, a scheme table)": the text of help messages and of the parser's refusals.
std::string method_names_text(method_system s);

/// An adaptive method's tolerance when none is typed, and its allowed range, in that system.
double default_tolerance(method_system s);

/// A method resolved for a system and its bodies.
struct resolved_method {
  std::string name;                    ///< as typed
  const method_family* family = nullptr;
  models::md_integrator splitting;     ///< splittings: the TV table, the rotor's kind, f
  std::vector<std::optional<schemes::scheme_table>> rotors;  ///< each body's table rotor (a table rotor with bodies given)
  double tolerance = 0;                ///< adaptive: absolute and relative

  method_kind kind() const { return family->kind; }
  bool adaptive() const { return kind() == method_kind::adaptive; }
  bool splitting_method() const { return kind() == method_kind::tv_splitting || kind() == method_kind::kepler_splitting; }
  /// Body b's table rotor, or nullptr (a listed rotor, or no bodies were given).
  const schemes::scheme_table* rotor_table(std::size_t b = 0) const { return b < rotors.size() && rotors[b] ? &*rotors[b] : nullptr; }
};

/// The one parser. `bodies` are the moments of the bodies the method steps (one per body type; binary:
/// the primary and the secondary): a table rotor is solved or read for each; with none, a table rotor is
/// left to the caller (spec.rotor_table names it). Throws bad_input, one line naming --integrator; an
/// unknown name lists the system's names.
resolved_method method_named(const std::string& text, method_system system, const std::vector<lie::moments_of_inertia>& bodies = {});
/// The same with the moments as doubles, each taken exactly (not through decimal text).
resolved_method method_named(const std::string& text, method_system system, const std::vector<models::vec3<double>>& bodies);

/// A double's moments as exact numbers: the value of each double, not a decimal rounding of it.
lie::moments_of_inertia exact_moments(const models::vec3<double>& I);

/// A free rotor resolved for one body: a listed rotor's name, or a table (ABC or RS, never TV).
struct free_rotor {
  std::string closed_form;                     ///< a listed rotor's name, or empty: `table`
  std::optional<schemes::scheme_table> table;  ///< the table resolved for the body
};

/// ROTOR of the grammar alone (LAMMPS's `rotor VALUE`): a listed rotor's name, or a table name resolved
/// by scheme_named with `policy`. Throws bad_input, its message starting with `what` ("rotor P1:BAC:9").
free_rotor free_rotor_named(const std::string& text, const lie::moments_of_inertia& body, const std::string& what,
                            foreign_table policy = foreign_table::refuse, const warning_sink& warn = {});

/// The values ROTOR takes, for help texts: "exact, sej4, a reference scheme, SCHEME:PERM:LABEL or a scheme-table file".
std::string rotor_values_text();

/// The family behind a LAMMPS fix style rigid/NAME/small, or nullptr.
const method_family* lammps_style_family(const std::string& style);
/// A family's LAMMPS fix style: "rigid/sier2/small".
std::string lammps_style_of(const method_family& f);

}  // namespace rotlie::runs
