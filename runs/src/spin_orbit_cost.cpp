#include "rotlie/runs/spin_orbit_cost.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/runs/spin_orbit_stepping.hpp"

namespace rotlie::runs {

const std::vector<spin_cost_case>& spin_cost_cases() {
  static const std::vector<spin_cost_case> cases = {
      {"Moon, synchronous, 100 orbits", "Moon", 0.0549, 0.1, 1.0, 0.05, 100},
      {"Mercury, 3:2, 100 orbits", "Mercury", 0.2056, 0.1, 1.5, 0.05, 100},
      {"Hyperion, omega0 = 2 n, 5 orbits", "Hyperion", 0.1, 0.3, 2.0, 0.2, 5},
  };
  return cases;
}

models::body_state<long double> spin_cost_reference(const spin_cost_case& c) {
  const auto body = spin_body_named(c.body);
  const auto I = spin_moments_in<long double>(body);
  const auto start = models::spin_orbit_start<long double>(I, c.theta0, c.omega0, c.obliquity);
  const long double T = boost::math::constants::two_pi<long double>() * static_cast<long double>(c.orbits);
  return step_spin_orbit<long double>(spin_method_named("odeint-rkf78:1e-18", body), I, c.e, start, T / 1000, 1000).state;
}

spin_cost_point spin_cost_point_of(const spin_cost_case& c, const models::body_state<long double>& reference, const std::string& name,
                                   double h, double min_cpu_s) {
  const auto body = spin_body_named(c.body);
  const auto method = spin_method_named(name, body);
  const auto I = spin_moments_in<double>(body);
  const auto start = models::spin_orbit_start<double>(I, c.theta0, c.omega0, c.obliquity);
  const long steps = method.adaptive ? 1 : std::max(1L, std::lround(c.orbits / h));
  const double T = boost::math::constants::two_pi<double>() * c.orbits;
  // an adaptive method starts from a trial step of 1/100 orbit and runs straight to T
  const double step = method.adaptive ? boost::math::constants::two_pi<double>() / 100 : T / static_cast<double>(steps);
  const long adaptive_steps = method.adaptive ? std::lround(T / step) : steps;
  spin_cost_point p;
  p.method = name;
  p.h = method.adaptive ? method.tolerance : h;
  int runs = 0;
  spin_outcome<double> out;
  do {
    out = step_spin_orbit<double>(method, I, c.e, start, method.adaptive ? T / static_cast<double>(adaptive_steps) : step,
                                  adaptive_steps);
    p.cpu_s += out.cpu_s;
    ++runs;
  } while (p.cpu_s < min_cpu_s && runs < 1000);
  p.cpu_s /= runs;
  p.evaluations = static_cast<double>(out.evaluations);
  models::mat3<double> ref;
  for (std::size_t i = 0; i < 9; ++i) ref.a[i] = static_cast<double>(reference.Q.a[i]);
  p.error = models::distance(out.state.Q, ref);
  return p;
}

double cpu_at_error(const std::vector<spin_cost_point>& curve, double error) {
  // the cheapest point at or below `error`, interpolated in log-log with the next cheaper point (above
  // it): the CPU time needed to reach the error; below round-off the curves turn up again and are not read
  auto pts = curve;
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.cpu_s < b.cpu_s; });
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const auto &a = pts[i - 1], &b = pts[i];
    if (b.error <= error && a.error > error && b.error > 0) {
      const double u = std::log(error / a.error) / std::log(b.error / a.error);
      return std::exp(std::log(a.cpu_s) + u * std::log(b.cpu_s / a.cpu_s));
    }
    if (b.error <= error) break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rotlie::runs
