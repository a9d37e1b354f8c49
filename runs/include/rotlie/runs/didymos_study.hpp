#pragma once
// The Didymos system as the report's "Binary asteroid" section shows it (docs/binary.md): its observables
// from two starts, the period change of an impulsive Δv at DART's geometry, and the plan of the sweep of
// error against CPU time. Plain numbers; the section formats them.
#include <string>
#include <vector>

#include "rotlie/runs/binary_study.hpp"

namespace rotlie::runs {

/// s: a whole number of every step of the cost sweep, near one mutual orbit (11.73 h).
inline constexpr double didymos_orbit_unit_s = 42240;

/// `--system didymos` at an order, integrator, step h (s) and span T (s). gubas_start: the public GUBAS
/// example's start (1200 m, 0.175704287113523 m/s, frames aligned) instead of the circular, balanced one.
/// Each registered force term (binary_terms.hpp) at its example values on the Didymos system: the
/// relative position's change against the same run without it, and its values at the end.
struct term_effect {
  std::string name, values;
  double separation_change_km = 0;  ///< |r_with − r_without| at the end
  double phase_change_deg = 0;      ///< the change of the mutual orbit's angle at the end
  std::string values_at_end;        ///< its JSON values at the end
};
std::vector<term_effect> didymos_term_effects(double T);

binary_setup didymos_setup(int order, const std::string& integrator, double h, double T, bool gubas_start);

/// `days` rounded to whole minutes, in seconds: the span of the benchmark and DART runs.
double didymos_span_s(double days);

/// One start at one order, read over T by KEPLER4 at h = 60 s, sampled every 5 steps.
struct didymos_benchmark_row {
  bool gubas_start = false;
  int order = 2;
  binary_observables observed;
};

/// The circular start, then the GUBAS one, each at orders 2, 4, 6 and 8.
std::vector<didymos_benchmark_row> didymos_benchmark(double T);

/// A momentum transfer: Δv = β m U / M₂ (m in kg, U in km/s), against the secondary's orbital motion.
struct dart_impact {
  double mass_kg = 0, speed_km_s = 0, beta = 1;
};

struct dart_row {
  double dv_km_s = 0;
  double period_h = 0;    ///< the mean mutual orbit period after the impulse
  double change_min = 0;  ///< against the period before
};

struct dart_result {
  double secondary_mass_kg = 0;
  double dv_km_s = 0;          ///< β m U / M₂
  double period_before_h = 0;
  std::vector<dart_row> rows;  ///< at Δv, Δv/2 and 2Δv
};

/// The circular start at order 4 (KEPLER4, h = 60 s, over T seconds, sampled every 5 steps), before and
/// after the impulse.
dart_result dart_period_change(const dart_impact& impact, double T);

/// One push of DART's β: the period change and the secondary's excitation after it.
struct dart_beta_row {
  double beta = 0, dv_km_s = 0, tilt_deg = 0;  ///< tilt: the push turned out of the orbit plane
  double change_min = 0;                       ///< the mean mutual orbit period after, against before
  double libration_amplitude_deg = 0;
  double npa_angle_max_deg = 0;  ///< the secondary's G off its maximum-moment axis, largest over the run
  bool tumbling = false;
};

/// DART's push at each β (impact's mass and speed, along the track), and once at `tilted_beta` turned
/// `tilt_deg` out of the orbit plane: the circular start at order 4 (KEPLER4, h = 60 s, over T seconds).
/// The β that gives `target_min` (linear interpolation between the grid's neighbours; 0 if outside).
struct dart_beta_result {
  double period_before_h = 0, secondary_mass_kg = 0, beta_for_target = 0, target_min = 0;
  std::vector<dart_beta_row> rows;  ///< the grid, then the tilted push
};
dart_beta_result dart_beta_sweep(const dart_impact& impact, const std::vector<double>& betas, double tilted_beta, double tilt_deg,
                                 double target_min, double T);

/// The report's sweep over `orbits` × didymos_orbit_unit_s: the TV splittings, the LGVI and RK4 at fixed
/// steps (three with quick, five otherwise), Odeint's RKF78 at three tolerances, against KEPLER4 at 7.5 s.
binary_cost_plan didymos_cost_plan(double orbits, bool quick);

}  // namespace rotlie::runs
