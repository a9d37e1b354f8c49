// binary: two rigid bodies in mutual gravity (the full two-body problem of binary asteroids), any of
// its integrators: the final state, the mutual gravity there, the conserved quantities' errors.
#include <iostream>

#include "commands.hpp"
#include "rotlie/runs/binary_io.hpp"
#include "rotlie/runs/binary_run.hpp"

namespace rotlie::app {

int run_binary(const binary_options& o) {
  const auto setup = runs::binary_setup_of({o.system, o.primary, o.secondary, o.density, o.mass, o.order, o.G, o.separation, o.primary_period, o.state,
                                            o.integrator, o.h, o.T, o.every});
  const auto sys = setup.system_model();
  const auto r = runs::binary_run(setup, [&](const runs::binary_sample& s) { std::cout << runs::binary_sample_json(s, sys).dump() << "\n"; });
  for (const auto& w : r.check.warnings) std::cerr << "rotlie: warning: " << w << "\n";
  if (o.json)
    std::cout << (setup.every > 0 ? runs::binary_json(r).dump() : runs::binary_json(r).dump(2)) << "\n";
  else
    std::cout << runs::binary_text(r);
  return 0;
}

}  // namespace rotlie::app
