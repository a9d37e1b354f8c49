#pragma once
// A run of an md scene the caller holds (REBOUND's shape): built from the request run_scene takes and
// checked the same way, advanced by integrate(t) to an absolute time in whole steps of h, and
// continued from where it stopped, so that integrate(T/2) then integrate(T) gives the bits of one
// integrate(T) and of the scene's run to T. It holds every system of the scene (free-water and
// dipole-field: the ensemble's runs, one molecule each), its step count and the integrator's
// composition, the states keeping their clock and cached forces.
#include <functional>
#include <memory>
#include <string>

#include "rotlie/models/small_matrix.hpp"
#include "rotlie/runs/scenes.hpp"

namespace rotlie::runs {

/// One body's state in double (real units: Å, g/mol·Å/fs; Q body → lab, G body-frame angular momentum).
struct md_body {
  models::vec3<double> q{}, p{};
  models::mat3<double> Q{};
  models::vec3<double> G{};
};

/// What a held run is of, as its scene checked it.
struct md_held_setup {
  std::string scene, integrator, scalar;
  double h_fs = 0;
  long runs = 1;
  unsigned long seed = 1;
};

/// The typed run behind md_simulation, made by a scene's `hold` (scenes.hpp).
class held_md_run {
 public:
  virtual ~held_md_run() = default;
  virtual void step() = 0;  ///< every system one step of h
  virtual long steps() const = 0;
  virtual long systems() const = 0;
  virtual long bodies() const = 0;  ///< per system
  virtual md_body body(long system, long i) const = 0;
  virtual double energy(long system) const = 0;     ///< kinetic + potential (kcal/mol)
  virtual double potential(long system) const = 0;  ///< V at the current configuration (kcal/mol)
  virtual long force_evaluations() const = 0;       ///< over the systems

  md_held_setup setup;
};

class md_simulation {
 public:
  /// The scene of request.scene at t = 0, its options checked as run_scene checks them (a foreign
  /// option refused, defaults filled; --T and --every do not matter here). Throws bad_input, also for
  /// a scene that cannot be held.
  explicit md_simulation(const scene_request& request);
  ~md_simulation();
  md_simulation(md_simulation&&) noexcept;
  md_simulation& operator=(md_simulation&&) noexcept;

  /// One step of h for every system.
  void step();
  /// To the absolute time t (ps): the whole steps whose end k·h is at most t, a step overshooting t by
  /// round-off counted (held_steps.hpp); none when t is not past the next step (the scene's run rounds
  /// T/h to the nearest step instead: the same steps for a T on the grid). Throws std::invalid_argument
  /// when t lies before the current step. stop(), when given, is asked before each step: true ends the
  /// call at the step reached.
  void integrate(double t_ps, const std::function<bool()>& stop = {});

  double t() const;  ///< k·h/1000, ps
  long steps() const;
  const md_held_setup& setup() const { return run_->setup; }
  long systems() const { return run_->systems(); }
  long bodies() const { return run_->bodies(); }
  md_body body(long system, long i) const;
  double energy(long system = 0) const;
  double potential(long system = 0) const;
  long force_evaluations() const { return run_->force_evaluations(); }

 private:
  std::unique_ptr<held_md_run> run_;
};

}  // namespace rotlie::runs
