#include "rotlie/runs/hyperion_study.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>

namespace rotlie::runs {

hyperion_section_summary hyperion_section_study(double rate_step, int orbits, long steps_per_orbit) {
  const double pi = boost::math::constants::pi<double>();
  const auto body = spin_body_named("Hyperion");
  hyperion_section_summary out;
  for (double w = 0.2; w <= 3.0 + 1e-9; w += rate_step) out.starts.push_back({0.0, w}), out.starts.push_back({pi / 2, w});
  out.section = planar_section(body, 0.1, out.starts, orbits, steps_per_orbit);
  const auto& sec = out.section;
  out.regular_floor = std::log(orbits) / orbits;
  for (std::size_t i = 0; i < sec.rate.size(); ++i)
    if (sec.lyapunov[static_cast<std::size_t>(sec.trajectory[i])] > spin_chaos_threshold)
      out.zone_lo = std::min(out.zone_lo, sec.rate[i]), out.zone_hi = std::max(out.zone_hi, sec.rate[i]);
  for (std::size_t j = 0; j < sec.lyapunov.size(); ++j) {
    const double l = sec.lyapunov[j];
    out.chaotic += l > spin_chaos_threshold, out.largest = std::max(out.largest, l);
    if (l > spin_chaos_threshold) out.chaotic_rates[j % 2].push_back(out.starts[j].second);
  }
  out.lyapunov_time_orbits = 1 / out.largest;
  out.lyapunov_time_days = hyperion_period_days / out.largest;
  return out;
}

double e_folding_rate(const std::vector<double>& x, double lo, double hi) {
  long first = -1, last = -1;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (first < 0 && x[k] > lo) first = static_cast<long>(k);
    if (last < 0 && x[k] > hi) last = static_cast<long>(k);
  }
  if (first < 0 || last <= first) return std::nan("");
  return std::log(x[static_cast<std::size_t>(last)] / x[static_cast<std::size_t>(first)]) / static_cast<double>(last - first);
}

synchronous_tilt synchronous_tilt_study(int tilt_orbits, int orbits, long steps_per_orbit) {
  const auto hyperion = spin_body_named("Hyperion"), moon = spin_body_named("Moon");
  const auto I = spin_moments(hyperion), Im = spin_moments(moon);
  synchronous_tilt out;
  out.rate = resonant_rate(hyperion, 0.1, 1.0, 0.5, 1.5, steps_per_orbit);
  out.obliquity = obliquity_history(hyperion, 0.1, models::spin_orbit_start<double>(I, 0.0, out.rate, 1e-6), tilt_orbits, steps_per_orbit);
  out.planar_lyapunov = lyapunov_per_orbit(hyperion, 0.1, models::spin_orbit_start<double>(I, 0.0, out.rate, 0.0), orbits, steps_per_orbit);
  out.growth = e_folding_rate(out.obliquity, 1e-5, 1e-2);
  out.e_folding_orbits = 1 / out.growth;
  out.moon_rate = resonant_rate(moon, 0.0549, 1.0, 0.9, 1.1, steps_per_orbit);
  out.moon_obliquity = obliquity_history(moon, 0.0549, models::spin_orbit_start<double>(Im, 0.0, out.moon_rate, 1e-6), tilt_orbits, steps_per_orbit);
  for (const double x : out.moon_obliquity) out.moon_largest = std::max(out.moon_largest, x);
  return out;
}

std::vector<hyperion_state_exponent> hyperion_state_exponents(double synchronous_rate, int orbits, long steps_per_orbit) {
  const double pi = boost::math::constants::pi<double>();
  const auto body = spin_body_named("Hyperion");
  const auto I = spin_moments(body);
  const struct {
    const char* what;
    double theta0, omega0, obliquity;
  } starts[] = {{"synchronous, tilted 1e-3 rad", 0.0, synchronous_rate, 1e-3},
                {"θ₀ = π/2, θ'₀ = 1 n, planar", pi / 2, 1.0, 0.0},
                {"θ'₀ = 1 n about C, tilted 0.5 rad", 0.0, 1.0, 0.5},
                {"θ'₀ = 4.2 n about C, tilted 0.5 rad", 0.0, 4.2, 0.5},
                {"θ'₀ = 4.2 n about C, planar", 0.0, 4.2, 0.0}};
  std::vector<hyperion_state_exponent> out;
  for (const auto& start : starts) {
    auto& s = out.emplace_back();
    s.what = start.what, s.theta0 = start.theta0, s.omega0 = start.omega0, s.obliquity = start.obliquity;
    s.exponent = lyapunov_per_orbit(body, 0.1, models::spin_orbit_start<double>(I, s.theta0, s.omega0, s.obliquity), orbits, steps_per_orbit);
    s.regular = s.exponent < spin_chaos_threshold;
    s.lyapunov_time_orbits = 1 / s.exponent;
    s.lyapunov_time_days = hyperion_period_days / s.exponent;
  }
  return out;
}

}  // namespace rotlie::runs
