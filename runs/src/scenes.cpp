#include "rotlie/runs/scenes.hpp"

#include <algorithm>

#include "rotlie/runs/md_simulation.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {
namespace {

// "a, b or c"
std::string listed(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}

const scene_option* option_of(const scene& s, const std::string& name) {
  const auto it = std::find_if(s.options.begin(), s.options.end(), [&](const scene_option& o) { return o.name == name; });
  return it == s.options.end() ? nullptr : &*it;
}

// The scenes that take option `name`.
std::vector<std::string> scenes_taking(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& s : scenes())
    if (option_of(s, name)) names.push_back(s.name);
  return names;
}

}  // namespace

const scene& scene_named(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& s : scenes()) {
    if (s.name == name) return s;
    names.push_back(s.name);
  }
  throw bad_input(one_line("--scene must be " + listed(names) + ", got '" + name + "'"));
}

std::vector<scene_option> all_scene_options() {
  std::vector<scene_option> all;
  for (const auto& s : scenes())
    for (const auto& o : s.options)
      if (std::none_of(all.begin(), all.end(), [&](const scene_option& a) { return a.name == o.name; })) all.push_back(o);
  for (auto& o : all) {
    std::vector<std::string> defaults;
    for (const auto& s : scenes())
      if (const auto* mine = option_of(s, o.name); mine && !mine->default_text.empty())
        defaults.push_back(mine->default_text + " for " + s.name);
    const auto takers = scenes_taking(o.name);
    const std::string where = takers.size() < scenes().size() ? listed(takers) + ": " : "";
    o.help = where + o.help + (defaults.empty() ? "" : " (default: " + listed(defaults) + ")");
    o.default_text.clear();  // differs per scene
  }
  return all;
}

namespace {

// The request with every option of scene s (defaults filled), a foreign option refused.
scene_request full_request(const scene& s, const scene_request& request) {
  scene_request full = request;
  for (const auto& [name, value] : request.options) {
    if (option_of(s, name)) continue;
    const auto takers = scenes_taking(name);
    if (takers.empty()) throw bad_input(one_line("no scene takes the option " + name));
    throw bad_input(takers.size() == 1 ? name + " applies to the " + takers[0] + " scene only"
                                       : name + " does not apply to the " + s.name + " scene");
  }
  for (const auto& o : s.options) full.options.try_emplace(o.name, o.default_text);
  return full;
}

}  // namespace

scene_result run_scene(const scene_request& request) {
  const auto& s = scene_named(request.scene);
  return s.run(full_request(s, request));
}

std::unique_ptr<held_md_run> hold_scene(const scene_request& request) {
  const auto& s = scene_named(request.scene);
  if (!s.hold) {
    std::string held;
    for (const auto& other : scenes())
      if (other.hold) held += (held.empty() ? "" : ", ") + other.name;
    throw bad_input("--scene " + s.name + " cannot be held as a simulation (" + held + " can)");
  }
  return s.hold(full_request(s, request));
}

}  // namespace rotlie::runs
