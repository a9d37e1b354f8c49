#pragma once
// Mercury in 3:2 and the Moon in 1:1 (the report's "Spin–orbit" section): each started on the symmetric
// periodic orbit of its resonance (no free libration), its forced libration measured against first-order
// theory. Plain numbers; the section formats them.
#include <string>
#include <vector>

#include "rotlie/runs/spin_orbit_science.hpp"

namespace rotlie::runs {

/// Mercury's forced libration in 3:2 to first order (Margot et al. 2007's form, the whole body's C):
/// (3/2)((B − A)/C)(1 − 11e² + 959e⁴/48), radians.
double forced_libration_3_2(double asphericity, double e);

/// A synchronous body's: φ'' + ω₀²φ = 2e ω₀² sin M to first order in e, amplitude 2e ω₀²/(1 − ω₀²),
/// ω₀² = 3(B − A)/C.
double forced_libration_1_1(double omega0_squared, double e);

struct forced_libration {
  std::string body;
  double p = 1, e = 0;
  double rate = 0;      ///< the periodic orbit's θ'/n at pericentre (bisection)
  resonance_run run;    ///< SIER4 at h = 1/200 orbit
  double theory = 0;    ///< first order, radians
  double ratio = 0;     ///< measured forced amplitude over theory
};

/// Mercury (3:2, e = 0.2056), then the Moon (1:1, e = 0.0549), each over `orbits` orbits.
std::vector<forced_libration> forced_librations(int orbits);

}  // namespace rotlie::runs
