#pragma once
// What the scene entries share: reading an option of a request, the shortest decimal of a number,
// and the rotor table of SIER2/X or SIER4/X solved for the scene's body.
#include <charconv>
#include <optional>
#include <string>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/scenes.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs::scene_support {

/// The text of option `name` (run_scene has filled in every default).
inline const std::string& option(const scene_request& r, const std::string& name) { return r.options.at(name); }

/// The shortest decimal that reads back as x (so that long double and float128 read the same number).
inline std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, ec == std::errc() ? end : buf);
}

/// --integrator parsed once; the message names the option.
inline models::md_integrator integrator_named(const std::string& name) {
  try {
    return models::md_integrator_named(name);
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--integrator: ") + e.what());
  }
}

/// Runs f; a std::invalid_argument from the models (a value they refuse) becomes bad_input.
template <class F>
decltype(auto) as_bad_input(F&& f) {
  try {
    return f();
  } catch (const bad_input&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw bad_input(e.what());
  }
}

/// The free-rotation table of SIER2/X or SIER4/X: a reference name, or SCHEME:PERM:LABEL solved for
/// the body `body_text`; a table file solved for another body is refused. Empty for the integrators
/// with a rotor of their own.
inline std::optional<schemes::scheme_table> rotor_table(const models::md_integrator& integrator, const std::string& body_text) {
  if (integrator.rotor != models::rotor_kind::table) return std::nullopt;
  try {
    return scheme_named(integrator.rotor_table, numeric_body(body_text), foreign_table::refuse);
  } catch (const bad_input& e) {
    std::string why = e.what();
    if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
    throw bad_input("--integrator " + integrator.name + ": " + why);
  }
}

}  // namespace rotlie::runs::scene_support
