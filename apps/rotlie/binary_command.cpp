// binary: two rigid bodies in mutual gravity (the full two-body problem of binary asteroids), any of
// its integrators: the final state, the mutual gravity there, the conserved quantities' errors.
#include <iostream>

#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"

namespace rotlie::app {

int run_binary(const binary_options& o) {
  runs::binary_request request;
  request.system = o.system, request.primary = o.primary, request.secondary = o.secondary, request.density = o.density, request.mass = o.mass;
  request.order = o.order, request.G = o.G, request.separation = o.separation, request.primary_period = o.primary_period;
  request.state_file = o.state, request.integrator = o.integrator, request.h = o.h, request.T = o.T, request.every = o.every;
  request.force = o.force, request.impulse = o.impulse, request.observe = o.observe;
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
