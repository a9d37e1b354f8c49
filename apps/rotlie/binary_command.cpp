// binary: two rigid bodies in mutual gravity (the full two-body problem of binary asteroids), any of
// its integrators: the final state, the mutual gravity there, the conserved quantities' errors.
#include <iostream>

#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/binary_fields.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"

namespace rotlie::app {

int run_binary(const binary_options& o) {
  runs::binary_request request;
  for (const auto& f : runs::binary_fields()) {
    if (f.type == runs::binary_field::kind::flag)
      request.*f.flag = o.flags.at(f.name);
    else
      request.*f.text = o.fields.at(f.name);
  }
  for (const auto& [name, text] : o.terms)
    if (!text.empty()) request.terms[name] = text;
  const auto setup = runs::binary_setup_of(request);
  const auto sys = setup.system_model();
  progress_line progress;  // on a terminal only
  const auto r = runs::binary_run(
      setup, [&](const runs::binary_sample& s) { std::cout << runs::binary_sample_json(s, sys).dump() << "\n"; },
      [&](double done) { progress.show("binary: " + std::to_string(static_cast<int>(100 * done)) + " % of " + std::to_string(setup.steps) + " steps"); });
  for (const auto& w : r.check.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  if (o.json)
    std::cout << (setup.every > 0 ? runs::binary_json(r).dump() : runs::binary_json(r).dump(2)) << "\n";
  else
    std::cout << runs::binary_text(r);
  return 0;
}

}  // namespace rotlie::app
