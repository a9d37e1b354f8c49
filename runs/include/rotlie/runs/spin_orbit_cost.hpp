#pragma once
// Error against CPU time in the spin–orbit scene (issue 24's question): each integrator run in double
// at a step (or, for Odeint, a tolerance), its final attitude compared with a long double reference
// (Odeint's RKF78 at tolerance 1e-18, none of the methods measured), its stepping CPU time taken as
// the mean of repeated runs. bench/spin_bench and the report's "Spin–orbit" section call this.
#include <string>
#include <vector>

#include "rotlie/models/rigid_body.hpp"

namespace rotlie::runs {

/// A body in a state of its own: named body, orbit, initial state of the command line, length.
struct spin_cost_case {
  std::string label, body;
  double e = 0, theta0 = 0, omega0 = 1, obliquity = 0, orbits = 1;
};

/// The Moon near synchronous rotation, Mercury near 3:2, Hyperion tumbling (slightly tilted each, so
/// that the motion is 3-D).
const std::vector<spin_cost_case>& spin_cost_cases();

/// The final state of a case by RKF78 in long double at tolerance 1e-18.
models::body_state<long double> spin_cost_reference(const spin_cost_case& c);

struct spin_cost_point {
  std::string method;
  double h = 0;              ///< step as a fraction of the orbit (splittings); the tolerance (Odeint)
  double error = 0;          ///< Frobenius distance of the final attitude from the reference
  double cpu_s = 0;          ///< CPU seconds of one run (mean of the repeats)
  double evaluations = 0;    ///< torque evaluations of one run
};

/// One method at one step (splittings) or tolerance (odeint-*: h is ignored and the name carries
/// ":TOL"), repeated until min_cpu_s of CPU time is spent.
spin_cost_point spin_cost_point_of(const spin_cost_case& c, const models::body_state<long double>& reference, const std::string& method,
                                   double h, double min_cpu_s);

/// CPU seconds a curve (points of one method) needs for `error`: the cheapest point at or below it,
/// interpolated in log-log with the next cheaper one; NaN when the cheapest point is already below it or
/// none reaches it.
double cpu_at_error(const std::vector<spin_cost_point>& curve, double error);

}  // namespace rotlie::runs
