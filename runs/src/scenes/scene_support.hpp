#pragma once
// What the scene entries share: reading an option of a request, the shortest decimal of a number,
// and models' refusals as bad input. The integrator is resolved by runs/md_methods.hpp.
#include <charconv>
#include <optional>
#include <string>

#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/md_methods.hpp"
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

}  // namespace rotlie::runs::scene_support
