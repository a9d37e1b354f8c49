#include "rotlie/runs/spin_islands_study.hpp"

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <stdexcept>

#include "rotlie/runs/hyperion_study.hpp"

namespace rotlie::runs {

spin_islands hyperion_islands(double e, double grid_step, int grid_orbits, long steps_per_orbit) {
  const double half_pi = boost::math::constants::pi<double>() / 2;
  const auto body = spin_body_named("Hyperion");
  const auto I = spin_moments(body);
  spin_islands out;
  out.omega0 = std::sqrt(3 * (I[1] - I[0]) / I[2]);
  // brackets around each symmetric orbit's pericentre rate (a strong asphericity moves them far from p n)
  const double brackets[][4] = {{0.5, half_pi, 0.8, 1.0}, {1, 0, 0.4, 0.7}, {1.5, 0, 1.85, 2.1}, {1.5, half_pi, 1.2, 1.4}, {2, 0, 2.2, 2.45}, {2.5, 0, 2.6, 2.8}};
  for (const auto& [p, theta0, lo, hi] : brackets) {
    auto& f = out.orbits.emplace_back();
    f.p = p, f.theta0 = theta0, f.lo = lo, f.hi = hi;
    try {
      f.rate = resonant_rate(body, e, f.p, f.lo, f.hi, 200, f.theta0);
    } catch (const std::runtime_error&) {  // no sign change in the bracket: no such orbit there
      f.rate = std::nan("");
    }
    f.found = std::isfinite(f.rate);
    if (!f.found) continue;
    f.trace = planar_map_trace(body, e, f.theta0, f.rate, 200);
    f.turns = spin_winding(body, e, f.theta0, f.rate, 1, 200);
    f.elliptic = std::abs(f.trace) < 2;
  }
  for (const double p : {1.0, 1.5, 2.0}) {
    const double H = cayley_coefficient(p, e);
    out.widths.push_back({p, H, out.omega0 * std::sqrt(std::abs(H))});
  }
  const double w1 = out.widths[0].half_width, w32 = out.widths[1].half_width, w2 = out.widths[2].half_width;
  out.overlap_1_to_3_2 = (w1 + w32) / 0.5;
  out.overlap_3_2_to_2 = (w32 + w2) / 0.5;
  out.band_lo = 1 - w1;
  out.band_hi = 2 + w2;
  out.grid_step = grid_step;
  for (const double theta0 : {0.0, half_pi})
    for (double w = 1.2; w <= 2.1 + 1e-9; w += grid_step) {
      ++out.starts;
      const double l = lyapunov_per_orbit(body, e, models::spin_orbit_start<double>(I, theta0, w, 0.0), grid_orbits, steps_per_orbit);
      if (l >= spin_chaos_threshold) continue;
      ++out.regular;
      out.regular_turns.push_back(spin_winding(body, e, theta0, w, grid_orbits, steps_per_orbit));
    }
  return out;
}

}  // namespace rotlie::runs
