#include "rotlie/runs/spin_orbit_drift.hpp"

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/runs/spin_orbit_stepping.hpp"

namespace rotlie::runs {
namespace {

template <class T>
spin_track track_in(const spin_drift_case& c, const spin_method& method, long steps_per_orbit, const std::vector<long>& checkpoints) {
  const auto body = spin_body_named(c.body);
  const auto I = spin_moments_in<T>(body);
  const auto start = models::spin_orbit_start<T>(I, T(c.theta0), T(c.omega0), T(c.obliquity));
  const T orbit = boost::math::constants::two_pi<T>();
  spin_track out;
  out.method = method.name;
  out.long_double = std::is_same_v<T, long double>;
  // a splitting observes every step and keeps each orbit's end; Odeint lands on every orbit
  const long per_orbit = method.adaptive ? 1 : steps_per_orbit;
  const T h = orbit / T(per_orbit);
  std::size_t next = 0;
  const double cpu0 = models::thread_cpu_seconds();
  step_spin_orbit<T>(method, I, T(c.e), start, h, checkpoints.back() * per_orbit, [&](long k, const T&, const models::body_state<T>& s) {
    if (k % per_orbit != 0 || next >= checkpoints.size() || k / per_orbit != checkpoints[next]) return;
    models::mat3<long double> Q;
    for (std::size_t i = 0; i < 9; ++i) Q.a[i] = static_cast<long double>(s.Q.a[i]);
    out.orbits.push_back(checkpoints[next++]);
    out.Q.push_back(Q);
    out.cpu_s.push_back(models::thread_cpu_seconds() - cpu0);
  });
  return out;
}

}  // namespace

const std::vector<spin_drift_case>& spin_drift_cases() {
  // steps: the splittings' error after 100 orbits near 1e-9 (bench/spin_bench's curves; Hyperion's
  // spin of 4.2 n under a torque a thousand times the Moon's needs 1600 steps an orbit for 1e-8)
  static const std::vector<spin_drift_case> cases = {
      {"Moon, synchronous", "Moon", 0.0549, 0.1, 1.0, 0.05, 50},
      {"Mercury, 3:2", "Mercury", 0.2056, 0.1, 1.5, 0.05, 100},
      {"Hyperion, 4.2 n about C tilted 0.5 rad", "Hyperion", 0.1, 0.0, 4.2, 0.5, 1600},
  };
  return cases;
}

spin_track spin_track_of(const spin_drift_case& c, const std::string& name, bool long_double, long steps_per_orbit,
                         const std::vector<long>& checkpoints) {
  if (checkpoints.empty() || checkpoints.front() < 1) throw std::invalid_argument("spin_track_of: checkpoints must be positive orbits");
  for (std::size_t i = 1; i < checkpoints.size(); ++i)
    if (checkpoints[i] <= checkpoints[i - 1]) throw std::invalid_argument("spin_track_of: checkpoints must increase");
  auto method = spin_method_named(name, spin_body_named(c.body));  // a dedicated table is solved here, before the clock
  // Odeint lands on every orbit but starts from a trial step of 1/100 orbit (as spin_cost_point_of): a
  // first trial of a whole orbit can overflow, and a non-finite error estimate passes Odeint's test
  method.first_step = static_cast<double>(boost::math::constants::two_pi<long double>() / 100);
  return long_double ? track_in<long double>(c, method, steps_per_orbit, checkpoints) : track_in<double>(c, method, steps_per_orbit, checkpoints);
}

long double attitude_angle(const models::mat3<long double>& a, const models::mat3<long double>& b) {
  models::mat3<long double> r;  // aᵀ b
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(0, i) * b(0, j) + a(1, i) * b(1, j) + a(2, i) * b(2, j);
  // sin θ from the antisymmetric part, cos θ from the trace: atan2 keeps small angles to full precision
  const long double x = r(2, 1) - r(1, 2), y = r(0, 2) - r(2, 0), z = r(1, 0) - r(0, 1);
  const long double s = std::sqrt(x * x + y * y + z * z) / 2, co = (r(0, 0) + r(1, 1) + r(2, 2) - 1) / 2;
  return std::atan2(s, co);
}

std::string rkf78_tolerance_at_equal_cpu(const spin_drift_case& c, long orbits) {
  const double target = spin_track_of(c, "SIER4", false, c.steps_per_orbit, {orbits}).cpu_s.back();
  std::string best;
  double best_ratio = std::numeric_limits<double>::infinity();
  for (const char* tol : {"1e-8", "1e-9", "1e-10", "1e-11", "1e-12", "1e-13", "1e-14", "1e-15"}) {
    const double cpu = spin_track_of(c, std::string("odeint-rkf78:") + tol, false, 1, {orbits}).cpu_s.back();
    const double ratio = std::abs(std::log(cpu / target));
    if (ratio < best_ratio) best_ratio = ratio, best = tol;
  }
  return best;
}

}  // namespace rotlie::runs
