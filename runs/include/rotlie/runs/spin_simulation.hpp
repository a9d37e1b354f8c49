#pragma once
// A spin–orbit run the caller holds (REBOUND's shape): built from the checked setup spin_run takes,
// advanced by integrate(t) to an absolute time in whole steps of setup.h, and continued from where it
// stopped, so that integrate(T/2) then integrate(T) gives the bits of one integrate(T) and of
// spin_run to T. It holds the state, the step count and the integrator's instance (the splitting's
// composition, clock and cached torques, or Odeint's stepper and its step size) in the setup's scalar.
#include <functional>
#include <memory>

#include "rotlie/models/small_matrix.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

class spin_simulation {
 public:
  /// At t = 0 from the setup's start; its step is setup.h (setup.T and setup.steps define it, as in
  /// spin_run: h = 2π T/steps in the scalar); setup.every is not used.
  explicit spin_simulation(const spin_setup& setup);
  ~spin_simulation();
  spin_simulation(spin_simulation&&) noexcept;
  spin_simulation& operator=(spin_simulation&&) noexcept;

  /// One step of setup.h.
  void step();
  /// To the absolute time t (orbits): the whole steps whose end k·h is at most t, a step overshooting t
  /// by round-off counted (held_steps.hpp); none when t is not past the next step. Throws
  /// std::invalid_argument when t lies before the current step. stop(), when given, is asked before each
  /// step: true ends the call at the step reached (an adaptive run's budget grows with t).
  void integrate(double t, const std::function<bool()>& stop = {});

  double t() const;  ///< k·setup.h, orbits
  long steps() const;
  const spin_setup& setup() const { return setup_; }
  models::mat3<double> Q() const;           ///< attitude: columns the body axes A, B, C in the inertial frame
  models::vec3<double> G() const;           ///< angular momentum in the body frame
  models::vec3<double> omega_body() const;  ///< angular velocity in the body frame (units of n)
  double theta() const;                     ///< the A axis' angle in the inertial xy plane
  double energy() const;                    ///< T + V(t) at the integrator's clock
  long evaluations() const;                 ///< torque evaluations (right-hand sides for Odeint)

  class held;

 private:
  spin_setup setup_;
  std::unique_ptr<held> held_;
};

}  // namespace rotlie::runs
