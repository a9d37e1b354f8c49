#pragma once
// Long runs of the spin–orbit scene (issue 24's "10⁴–10⁶ orbits (secular drift)"): the attitude error
// of a method in double after 10², 10³, … orbits, measured as the rotation angle of Q_refᵀ Q against a
// reference in long double. The reference is Odeint's RKF78 in long double at tolerance 1e-18; a
// second one, SIER4 (the exact rotor) in long double at a step four times finer than the measured
// splittings', bounds its error: where the two agree to δ, δ is what the measured errors are read to.
// Only regular (quasi-periodic) states have a long-run attitude error: a chaotic state forgets its
// start within a few Lyapunov times, and its error is that growth, not the method's.
// bench/spin_drift_bench and the report's "Spin–orbit" section call this.
#include <string>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

/// A regular state of a named body, with the step of the splittings measured on it.
struct spin_drift_case {
  std::string label, body;
  double e = 0, theta0 = 0, omega0 = 1, obliquity = 0;
  long steps_per_orbit = 100;
};

/// The Moon near synchronous rotation, Mercury near 3:2 and Hyperion spinning at 4.2 n about its
/// largest axis tilted 0.5 rad (regular in the scene, unlike the chaotic zone below 2.5 n).
const std::vector<spin_drift_case>& spin_drift_cases();

/// The attitude of one run at each checkpoint (orbits from the start, increasing).
struct spin_track {
  std::string method;
  bool long_double = false;
  std::vector<long> orbits;
  std::vector<models::mat3<long double>> Q;
  std::vector<double> cpu_s;  ///< stepping CPU seconds from the start to each checkpoint
};

/// Runs `method` (a `rotlie spin --integrator` name) from the case's start in double or long double:
/// a splitting at 1/steps_per_orbit orbit, an Odeint method landing on every orbit.
spin_track spin_track_of(const spin_drift_case& c, const std::string& method, bool long_double, long steps_per_orbit,
                         const std::vector<long>& checkpoints);

/// The rotation angle of aᵀ b (radians), accurate for small angles too.
long double attitude_angle(const models::mat3<long double>& a, const models::mat3<long double>& b);

/// RKF78's tolerance in double (from 1e-8 … 1e-15) whose CPU time over `orbits` orbits is nearest, in
/// ratio, to SIER4's at the case's step: the Odeint peer at equal CPU.
std::string rkf78_tolerance_at_equal_cpu(const spin_drift_case& c, long orbits);

}  // namespace rotlie::runs
