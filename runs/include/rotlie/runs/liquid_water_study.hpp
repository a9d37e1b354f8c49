#pragma once
// The measurements of van Zon & Schofield's section V.C (the report's section "Liquid water"): the NVE
// sweep of every integrator over its steps on 512 TIP3P molecules, the fitted slopes, g_OO(r), and the
// side by side with LAMMPS (single point and timed NVE). Plain numbers; reports/liquid_water_section
// formats and draws them.
#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/models/scenes/liquid_water_experiment.hpp"

namespace rotlie::runs {

/// The run sizes of the study.
struct liquid_water_budget {
  int runs;
  double run_ps, equilibration_ps, rdf_ps;
  long lammps_steps;
};

/// One step of one integrator's sweep: the run's result, or why it failed (a non-finite state).
struct liquid_water_point {
  double h_fs = 0;
  int f = 1;          ///< force evaluations per step
  int runs = 0;       ///< runs asked for
  double T_ps = 0;    ///< length of each run
  bool failed = false;
  std::string failure;  ///< the run's error when failed
  models::liquid_water_run_result result;  ///< when not failed
};

struct liquid_water_sweep {
  std::string integrator;
  std::vector<liquid_water_point> points;
};

/// One timed NVE of rotlie (threads) or LAMMPS (ranks) at h = 1 fs with the DSF pair style.
struct liquid_water_timing {
  int threads = 0;
  bool ran = false;
  double wall_ms = 0, cpu_ms = 0, ratio_percent = 0;  ///< per step; ΔE/ΔV (%)
};

struct liquid_water_study_result {
  double box_A = 0;                        ///< side of the cubic box of 512 molecules at 0.9973 g/cm³
  std::array<std::string, 3> moments_text;  ///< TIP3P's exact moments, g/mol·Å²
  std::vector<liquid_water_sweep> sweeps;
  /// ΔE/ΔV below this (%) is a point of its curve; at or above it the run left its stable range.
  double diverged_percent = 100;
  double v_per_molecule = 0, temperature = 0;  ///< SIER2 at h = 1 fs (0 when it did not run)
  std::vector<std::pair<double, double>> g_OO;  ///< (r Å, g_OO(r))
  /// LAMMPS's single point on the same configuration (lammps_ran false: lmp missing or failed)
  bool lammps_ran = false;
  double V_rotlie = 0, V_lammps = 0, worst_force = 0, force_scale = 0;
  std::vector<liquid_water_timing> rotlie_timings, lammps_timings;  ///< 1 and 2 threads / ranks
};

/// Least-squares slope of log ΔE/ΔV on log h/f over the sweep's stable points with h/f ≤ x_max
/// (models::fitted_order); NaN with fewer than two.
double liquid_water_slope(const liquid_water_sweep& sweep, double diverged_percent, double x_max);

/// Runs the study: `quick` and `full` choose the steps of each sweep as the report does.
liquid_water_study_result liquid_water_study(const liquid_water_budget& budget, bool quick, bool full,
                                             const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
