#pragma once
// The scenes a user can name (`rotlie md --scene NAME`, rotlie.md(...) from Python): one registry on
// the floor, so that a front end knows every scene, its options and its result without a line of its
// own. Adding a scene: its physics in models/, one file runs/src/scenes/NAME_scene.cpp with its entry
// (options, checks, run, JSON and text), and one line in runs/src/scene_list.cpp.
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotlie::runs {

class held_md_run;  // md_simulation.hpp

/// An option of a scene as the user types it ("--T"), its default as text ("" for none) and its help.
struct scene_option {
  std::string name, default_text, help;
};

/// What to run: the scene, the integrator, the step and the options the user gave ("--T" → "5").
struct scene_request {
  std::string scene, integrator, h;
  std::map<std::string, std::string> options;
  std::function<void(const std::string&)> progress;  ///< one line per stage of a long run (may be empty)
};

/// A finished run: the JSON a front end prints with --json (a contract: fields are added, never
/// renamed), the human summary, and warnings (one line each) about what the numbers mean.
struct scene_result {
  nlohmann::json json;
  std::string text;
  std::vector<std::string> warnings;
};

/// One scene. `run` receives the request with every option of the scene present (defaults filled);
/// `hold`, when the scene has one, builds from such a request the run md_simulation holds.
struct scene {
  std::string name, summary;
  std::vector<scene_option> options;
  scene_result (*run)(const scene_request&) = nullptr;
  std::unique_ptr<held_md_run> (*hold)(const scene_request&) = nullptr;
};

/// Every scene, in the order the help lists them.
const std::vector<scene>& scenes();

/// The scene called `name`; throws bad_input listing the scenes otherwise.
const scene& scene_named(const std::string& name);

/// Every option name any scene takes, first appearance first, with one help text: the first
/// scene's help and each scene's default ("(default: 5 for free-water, 1 for liquid-water)").
std::vector<scene_option> all_scene_options();

/// Runs the request: the scene named, options foreign to it refused (bad_input, nothing run),
/// the defaults filled in. Bad values throw bad_input; a run that failed throws std::runtime_error.
scene_result run_scene(const scene_request& request);

/// The scene's run held at t = 0 (md_simulation), after run_scene's checks; bad_input for a scene
/// without `hold`.
std::unique_ptr<held_md_run> hold_scene(const scene_request& request);

}  // namespace rotlie::runs
