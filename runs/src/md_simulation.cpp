#include "rotlie/runs/md_simulation.hpp"

#include "rotlie/runs/held_steps.hpp"

namespace rotlie::runs {

md_simulation::md_simulation(const scene_request& request) : run_(hold_scene(request)) {}

md_simulation::~md_simulation() = default;
md_simulation::md_simulation(md_simulation&&) noexcept = default;
md_simulation& md_simulation::operator=(md_simulation&&) noexcept = default;

void md_simulation::step() { run_->step(); }

void md_simulation::integrate(double t_ps, const std::function<bool()>& stop) {
  const long target = held_steps_until(t_ps, run_->setup.h_fs / 1000, steps(), "md_simulation.integrate");
  while (steps() < target) {
    if (stop && stop()) return;
    run_->step();
  }
}

double md_simulation::t() const { return run_->setup.h_fs * static_cast<double>(steps()) / 1000; }  // as the trajectory's t_ps
long md_simulation::steps() const { return run_->steps(); }

md_body md_simulation::body(long system, long i) const {
  if (system < 0 || system >= systems() || i < 0 || i >= bodies())
    throw std::out_of_range("md_simulation: no body " + std::to_string(i) + " of system " + std::to_string(system));
  return run_->body(system, i);
}

double md_simulation::energy(long system) const {
  if (system < 0 || system >= systems()) throw std::out_of_range("md_simulation: no system " + std::to_string(system));
  return run_->energy(system);
}

double md_simulation::potential(long system) const {
  if (system < 0 || system >= systems()) throw std::out_of_range("md_simulation: no system " + std::to_string(system));
  return run_->potential(system);
}

}  // namespace rotlie::runs
