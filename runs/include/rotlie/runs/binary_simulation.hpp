#pragma once
// The full two-body problem as a simulation the user holds (REBOUND's shape): built from a checked
// setup (binary_run.hpp), it steps with the setup's method and step h, integrate(t) continues to an
// absolute time in whole steps, and a copy is a saved state (assigning it back restores it, the
// method's carried values too: an adaptive method's next trial step, a splitting's forces). The time
// after k steps is k·h, so integrate(T/2) then integrate(T) is the same arithmetic as one
// integrate(T): the states are equal bit for bit. binary_run is one integrate to T.
#include <functional>
#include <memory>

#include "rotlie/runs/binary_run.hpp"

namespace rotlie::runs {

class binary_stepper;
class binary_watch;

class binary_simulation {
 public:
  /// At the setup's start, t = 0; h must be positive. `check_every`: the conserved quantities are
  /// sampled every so many steps (and at the end of each integrate); 0 picks about 10⁴ samples over
  /// the setup's T, or one per 100 steps when T is 0.
  explicit binary_simulation(const binary_setup& setup, long check_every = 0);
  binary_simulation(const binary_simulation& other);
  binary_simulation& operator=(const binary_simulation& other);
  binary_simulation(binary_simulation&&) noexcept;
  binary_simulation& operator=(binary_simulation&&) noexcept;
  ~binary_simulation();

  /// One step. Throws binary_contact (the state is that of the step that touched).
  void step();

  /// Steps while the next step ends at or before t (within 1e-9 of a step): t is absolute. A t before
  /// now throws std::invalid_argument. `sample` receives the start (first call only) and every
  /// `every`-th step's state; `progress` the fraction of this call's steps done, about every 1 %.
  void integrate(double t, const std::function<void(const binary_sample&)>& sample = {}, const std::function<void(double)>& progress = {});

  /// The same, by a count of steps; `stop` (if given) is asked every 64 steps and ends the call early
  /// when it says so (the state that of the last step taken).
  void advance(long steps, const std::function<void(const binary_sample&)>& sample = {}, const std::function<void(double)>& progress = {},
               const std::function<bool()>& stop = {});

  double t() const { return static_cast<double>(steps_) * setup_.h; }
  long steps() const { return steps_; }
  double h() const { return setup_.h; }
  const models::binary_state<double>& state() const { return x_; }
  const models::binary_system<double>& system() const { return system_; }
  const binary_setup& setup() const { return setup_; }
  double energy() const;

  /// The run from the start to now, judged as binary_run judges it.
  binary_result result() const;

 private:
  binary_setup setup_;
  models::binary_system<double> system_;
  models::binary_state<double> x_;
  long steps_ = 0, check_every_ = 1;
  double cpu_s_ = 0;
  std::unique_ptr<binary_stepper> stepper_;
  std::unique_ptr<binary_watch> watch_;
};

}  // namespace rotlie::runs
