#pragma once
// The one resolver of a method for bodies under torques as a user names it (md's and spin's
// --integrator, Python's integrator=, LAMMPS's `rotor` keyword): the TV splitting and the free
// rotor, either a rotor of models/closed_form_rotors.hpp's list by its name or a scheme table
// resolved for the body (a reference name, SCHEME:PERM:LABEL solved for it, a table file solved for
// it). What comes out is typed: models/ never reads the name's text again.
#include <optional>
#include <string>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

/// A free rotor resolved for one body: a listed rotor's name, or a table (ABC or RS, never TV).
struct free_rotor {
  std::string closed_form;                     ///< a listed rotor's name, or empty: `table`
  std::optional<schemes::scheme_table> table;  ///< the table resolved for the body
};

/// `text` as LAMMPS's `rotor VALUE` takes it: a listed rotor's name, or a table name resolved by
/// scheme_named with `policy`. Throws bad_input, its message starting with `what` ("rotor P1:BAC:9").
free_rotor free_rotor_named(const std::string& text, const lie::moments_of_inertia& body, const std::string& what,
                            foreign_table policy = foreign_table::refuse, const warning_sink& warn = {});

/// A method of md and spin resolved for one body.
struct md_method {
  models::md_integrator spec;                  ///< the splitting and the rotor's kind
  std::optional<schemes::scheme_table> rotor;  ///< the table rotor resolved for the body (spec.table_rotor())
  const schemes::scheme_table* rotor_table() const { return rotor ? &*rotor : nullptr; }
};

/// SIER2, SIER4, MRDL, MRDL-reversed, SEJ4, SIER2/X, SIER4/X (X a listed rotor or a table) for the
/// body; a table file solved for another body is refused. Throws bad_input naming --integrator.
md_method md_method_named(const std::string& text, const lie::moments_of_inertia& body);

}  // namespace rotlie::runs
