#pragma once
// Where a scheme stops working: runs of length T at growing steps h, each compared with the exact
// flow at every step. A run fails when its mean attitude error exceeds a threshold, its energy
// error exceeds the same threshold (relative), |G| drifts beyond round-off, or a value is not
// finite. Every stage is an exact rotation, so |G| is kept and the energy stays between
// |G|²/(2 I_max) and |G|²/(2 I_min): a splitting scheme of this kind loses accuracy, it cannot
// diverge, and the scan reports where the loss sets in. Each run is models::integrate with the
// observers of free_body_observers.hpp.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/free_body_observers.hpp"
#include "rotlie/models/integrate.hpp"

namespace rotlie::models {

struct stability_point {
  double h = 0;
  double mean_error = 0;      ///< mean attitude error over the run (R^9 norm)
  double energy_error = 0;    ///< max |E − E0| / E0
  double momentum_error = 0;  ///< max ||G| − |G0|| / |G0|
  bool finite = true;
  std::string failure;        ///< empty when the run works
};

struct stability_scan_result {
  std::vector<stability_point> points;  ///< ascending h
  double last_working_h = 0;            ///< largest h below the first failure (0 if the first fails)
  double first_failing_h = std::numeric_limits<double>::infinity();
  std::string failure;                  ///< why the first failing run failed
};

/// One run of `steps` steps of size total_time/steps.
template <class T>
stability_point stability_run(const free_body_composition<T>& method, const body_state<T>& initial,
                              const exact_free_body<T>& exact, const T& total_time, long steps, double threshold) {
  stability_point p;
  const T h = total_time / static_cast<T>(steps);
  p.h = static_cast<double>(h);
  auto guard = stop_unless_finite<T>();
  flow_attitude_error<T> error(exact);
  invariant_drift<T> drift(method.system().moments(), initial);
  body_state<T> s = initial;
  integrate(method, s, h, steps, guard, error, drift);
  p.energy_error = drift.energy_error();  // up to the last finite step
  p.momentum_error = drift.momentum_error();
  if (guard.stopped()) {
    p.finite = false;
    p.failure = "not finite";
    return p;
  }
  p.mean_error = static_cast<double>(error.mean());
  if (p.mean_error > threshold)
    p.failure = "mean attitude error above threshold";
  else if (p.energy_error > threshold)
    p.failure = "energy error above threshold";
  else if (p.momentum_error > 1e3 * static_cast<double>(std::numeric_limits<T>::epsilon()) * static_cast<double>(steps))
    p.failure = "|G| not conserved";
  return p;
}

/// Runs at h = T/n for n from T/h_min down to 1 (about `per_octave` steps per factor 2 in h).
template <class T>
stability_scan_result stability_scan(const schemes::scheme_table& table, const vec3<T>& I, const body_state<T>& initial,
                                     const T& total_time, double h_min, int per_octave, double threshold) {
  if (!(h_min > 0) || !(total_time > 0) || per_octave < 1) throw std::invalid_argument("bad stability scan parameters");
  const auto method = free_body_method(table, I);
  const exact_free_body<T> exact(I, initial);
  stability_scan_result r;
  long previous = 0;
  for (double h = h_min; h <= static_cast<double>(total_time) * 1.0000001; h *= std::exp2(1.0 / per_octave)) {
    const long steps = std::max(1L, std::lround(static_cast<double>(total_time) / h));
    if (steps == previous) continue;
    previous = steps;
    r.points.push_back(stability_run(method, initial, exact, total_time, steps, threshold));
    const auto& p = r.points.back();
    if (!p.failure.empty() && r.failure.empty()) {
      r.failure = p.failure;
      r.first_failing_h = p.h;
    } else if (r.failure.empty()) {
      r.last_working_h = p.h;
    }
  }
  return r;
}

}  // namespace rotlie::models
