// md: a scene of the floor's registry (runs/scenes.hpp) on the command line: the request as typed,
// progress on stderr, the result as text or JSON on stdout, its warnings on stderr.
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/scenes.hpp"

namespace rotlie::app {

int run_md(const md_options& o) {
  progress_line progress;
  runs::scene_request request{o.scene, o.integrator, o.h, o.given, [&progress](const std::string& line) { progress.show(line); }};
  const auto result = runs::run_scene(request);
  print_answer(o.json, [&] { return result.json; }, [&] { return result.text; });
  for (const auto& w : result.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  return 0;
}

}  // namespace rotlie::app
