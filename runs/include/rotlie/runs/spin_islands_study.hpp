#pragma once
// Which resonances of Hyperion's planar spin keep an island (the report's "Spin–orbit" section): the
// symmetric periodic orbits of the pericentre map and the trace of their Jacobian, the resonance-overlap
// estimate (Chirikov, with Cayley's H), and starts on a finer grid through both 3:2 orbits' rates.
#include <vector>

#include "rotlie/runs/spin_orbit_science.hpp"

namespace rotlie::runs {

/// A symmetric p:1 orbit searched for at θ₀ (0 or π/2) between pericentre rates lo and hi.
struct island_orbit {
  double p = 1, theta0 = 0, lo = 0, hi = 0;
  bool found = false;
  double rate = 0;      ///< θ'/n at pericentre, when found
  double turns = 0;     ///< turns per orbit (p for an orbit of the resonance)
  double trace = 0;     ///< of the one-orbit map's Jacobian
  bool elliptic = false;  ///< |trace| < 2: an island surrounds it
};

/// The p:1 island's half-width in θ'/n, ω₀ √|H(p, e)|.
struct resonance_width {
  double p = 1, H = 0, half_width = 0;
};

struct spin_islands {
  double omega0 = 0;  ///< √(3(B − A)/C)
  std::vector<island_orbit> orbits;   ///< 1:2, 1:1, both 3:2, 2:1, 5:2
  std::vector<resonance_width> widths;  ///< p = 1, 3/2, 2
  double overlap_1_to_3_2 = 0, overlap_3_2_to_2 = 0;  ///< the half-widths' sums over the 0.5 between centres
  double band_lo = 0, band_hi = 0;                     ///< the overlapping islands' outer edges, θ'/n
  double grid_step = 0;
  int regular = 0, starts = 0;       ///< of the grid's starts, those below spin_chaos_threshold
  std::vector<double> regular_turns; ///< their mean rates, θ'/n
};

/// Hyperion at e; the periodic orbits at h = 1/200 orbit, the grid (θ₀ = 0 and π/2, θ'₀ = 1.2 to 2.1 n in
/// steps of grid_step) over grid_orbits orbits at h = 1/steps_per_orbit.
spin_islands hyperion_islands(double e, double grid_step, int grid_orbits, long steps_per_orbit);

}  // namespace rotlie::runs
