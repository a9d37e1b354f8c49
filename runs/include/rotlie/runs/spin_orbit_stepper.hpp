#pragma once
// One spin–orbit run held between calls, in the scalar T: the integrator's instance (the splitting's
// composition and state with its clock and cached torques, or Odeint's stepper with its step size),
// the step count k and the time. Stepping it k times, in one call or in many, gives the same bits:
// the loop behind step_spin_orbit and spin_simulation.
#include <memory>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/models/scenes/spin_orbit.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::runs {

template <class T>
class spin_orbit_stepper {
 public:
  /// The run of m on the body of moments I on an orbit of eccentricity e from `start` at t = 0, steps of
  /// h (time units: the orbital period is 2π). Throws bad_input for an Odeint method in float128.
  spin_orbit_stepper(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h);
  ~spin_orbit_stepper();
  spin_orbit_stepper(spin_orbit_stepper&&) noexcept;
  spin_orbit_stepper& operator=(spin_orbit_stepper&&) noexcept;

  /// One step, to (k + 1) h: an Odeint method lands there (its own steps in between).
  void step();
  /// An Odeint method straight to k h from where it is, landing on no step in between (so not the bits
  /// of k single steps); a splitting takes the steps one by one.
  void jump_to(long k);
  /// Odeint's budget of tried steps over the run's life (beyond, a step throws); no effect on a splitting.
  void set_step_budget(double steps);

  long steps() const { return k_; }
  const T& h() const { return h_; }
  /// The integrator's clock: fl(k h) (the engine's step_clock, or Odeint's landing time).
  const T& t() const;
  const models::body_state<T>& state() const;
  /// Torque evaluations (right-hand sides for Odeint).
  long evaluations() const;
  const models::spin_orbit_tide<T>& tide() const;

  struct engine;

 private:
  std::unique_ptr<engine> engine_;
  T h_{};
  long k_ = 0;
};

extern template class spin_orbit_stepper<double>;
extern template class spin_orbit_stepper<long double>;
extern template class spin_orbit_stepper<quad>;

}  // namespace rotlie::runs
