#pragma once
// One free rigid body integrated by a scheme, measured against the exact flow: the runs behind
// `rotlie integrate`, `order` and `exact` (and the Python module's), as plain results.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/models/small_matrix.hpp"
#include "rotlie/runs/scheme_names.hpp"

namespace rotlie::runs {

/// A scheme table with the body it runs on: the body's exact moments as text, read into the
/// scalar of each run once (models::moments_from_text).
struct free_body_input {
  schemes::scheme_table table;
  std::string inertia;
};

/// The scheme named for the body named (scheme_named, numeric_body). Throws bad_input.
free_body_input free_body_of(const std::string& scheme, const std::string& inertia, foreign_table policy,
                             const warning_sink& warn = {});

/// How a step is timed: the fastest of `repeats` runs from G(0) = (1, 1, 1) at h = 1/64, each of at least
/// `min_seconds` of this thread's CPU (models::cpu_seconds_per_unit_time; other processes only ever slow a
/// run down: cache, frequency).
struct step_timing {
  int repeats = 5;
  double min_seconds = 0.01;
};

/// This thread's CPU seconds per step of `table` on the double stepper for the body of moments I.
double cpu_seconds_per_step(const schemes::scheme_table& table, const models::vec3<double>& I, const step_timing& how = {});

/// T/h as a whole number of steps (at most 10^8). Throws bad_input.
long step_count(double total, double h);

/// `integrate`: h, T, the steps, the mean attitude error against the exact flow (with the
/// reference's estimate) and the CPU seconds of the stepping alone.
struct integrate_result {
  std::string scheme;
  double cost = 0;  ///< in C0 per step
  double h = 0, T = 0;
  long steps = 0;
  models::protocol_point point;
  double cpu_s = 0;
};
integrate_result integrate_run(const free_body_input& in, const models::vec3<double>& G0, double h, double T,
                               const std::function<void(long step, long steps)>& progress = {});

/// `order`: the paper's protocol (section 4.1) at levels first … last in the scalar named
/// (double, long-double, float128), fitted; CPU per point in double.
struct order_result {
  std::string scheme, scalar;
  int declared_order = 0;
  models::order_measurement measurement;
  std::vector<double> cpu_s;  ///< per point
};
order_result order_run(const free_body_input& in, const models::vec3<double>& G0, double T, int first, int last,
                       const std::string& scalar);

/// `exact`: the exact flow of the body from (identity, G0) at time T, with its error estimate.
struct exact_result {
  double T = 0;
  models::body_state<double> state;
  double error_estimate = 0;
};
exact_result exact_run(const lie::moments_of_inertia& body, const models::vec3<double>& G0, double T);

}  // namespace rotlie::runs
