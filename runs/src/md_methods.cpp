#include "rotlie/runs/md_methods.hpp"

#include <stdexcept>

#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

free_rotor free_rotor_named(const std::string& text, const lie::moments_of_inertia& body, const std::string& what,
                            foreign_table policy, const warning_sink& warn) {
  if (models::is_closed_form_rotor(text)) return {text, std::nullopt};
  free_rotor r;
  try {
    r.table = scheme_named(text, body, policy, warn);
  } catch (const bad_input& e) {
    std::string why = e.what();
    if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
    throw bad_input(what + ": " + why);
  }
  if (r.table->splitting == schemes::split::tv)  // the free rotation needs ABC or RS (free_rigid_body::check)
    throw bad_input(what + ": " + one_line(text) + " is a TV table (it splits free flight and kick, an integrator): the free rotation needs an ABC or RS table");
  return r;
}

md_method md_method_named(const std::string& text, const lie::moments_of_inertia& body) {
  md_method m;
  try {
    m.spec = models::md_integrator_named(text);
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--integrator: ") + e.what());
  }
  if (m.spec.table_rotor()) m.rotor = free_rotor_named(m.spec.rotor_table, body, "--integrator " + one_line(text)).table;
  return m;
}

}  // namespace rotlie::runs
