#pragma once
// Hyperion's chaos as the report's "Spin–orbit" section shows it (docs/spin_orbit.md): Wisdom, Peale &
// Mignard (1984)'s planar surface of section summarised, the tilt instability of the synchronous state
// (against the Moon's), and Lyapunov estimates of 3-D states. SIER4 in double throughout
// (spin_orbit_science.hpp); plain numbers, the section formats them.
#include <string>
#include <utility>
#include <vector>

#include "rotlie/runs/spin_orbit_science.hpp"

namespace rotlie::runs {

/// Above this finite-time Lyapunov estimate (per orbit) a start is called chaotic: a regular orbit's
/// estimate decays like log(N)/N, 0.05 per orbit at N = 100 and 0.007 at N = 1000.
inline constexpr double spin_chaos_threshold = 0.1;
/// Hyperion's orbital period in days (a quote): the scene's orbit in physical time.
inline constexpr double hyperion_period_days = 21.28;

/// The planar surface of section at e = 0.1 and what it shows.
struct hyperion_section_summary {
  std::vector<std::pair<double, double>> starts;  ///< (θ₀, θ'₀/n): θ₀ = 0 and π/2 alternating, θ'₀ from 0.2 to 3
  spin_section section;
  double regular_floor = 0;  ///< log(N)/N: a regular orbit's estimate after N orbits
  int chaotic = 0;           ///< starts above spin_chaos_threshold
  double largest = 0;        ///< the largest exponent, per orbit
  double lyapunov_time_orbits = 0, lyapunov_time_days = 0;  ///< of the largest
  std::vector<double> chaotic_rates[2];  ///< θ'₀/n of the chaotic starts at θ₀ = 0 and at π/2
  double zone_lo = 1e9, zone_hi = -1e9;  ///< the range of the chaotic orbits' pericentre rates
};
hyperion_section_summary hyperion_section_study(double rate_step, int orbits, long steps_per_orbit);

/// The e-folding rate per sample of a growing series: the log-slope between the first samples above lo
/// and above hi; NaN when it never grows from lo to hi.
double e_folding_rate(const std::vector<double>& x, double lo, double hi);

/// The synchronous periodic orbit tilted by 1e-6 rad, Hyperion's (e = 0.1) and the Moon's (e = 0.0549).
struct synchronous_tilt {
  double rate = 0;             ///< Hyperion's synchronous orbit: θ'/n at pericentre
  double planar_lyapunov = 0;  ///< its estimate in the plane over `orbits`
  std::vector<double> obliquity;       ///< Hyperion's, rad, at each pericentre
  double growth = 0;                   ///< its e-folding rate per orbit between 1e-5 and 1e-2 rad
  double e_folding_orbits = 0;         ///< 1 / growth
  double moon_rate = 0;
  std::vector<double> moon_obliquity;
  double moon_largest = 0;
};
synchronous_tilt synchronous_tilt_study(int tilt_orbits, int orbits, long steps_per_orbit);

/// A 3-D start of Hyperion and its Lyapunov estimate.
struct hyperion_state_exponent {
  std::string what;
  double theta0 = 0, omega0 = 0, obliquity = 0;
  double exponent = 0;  ///< per orbit
  bool regular = false; ///< below spin_chaos_threshold
  double lyapunov_time_orbits = 0, lyapunov_time_days = 0;
};
/// The synchronous state tilted 1e-3 rad (at its rate `synchronous_rate`), a planar start at π/2, and
/// spins about C at 1 and 4.2 n, tilted and not.
std::vector<hyperion_state_exponent> hyperion_state_exponents(double synchronous_rate, int orbits, long steps_per_orbit);

}  // namespace rotlie::runs
