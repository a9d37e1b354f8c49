#pragma once
// The measurements of van Zon & Schofield's sections V.A-B (the report's section "van Zon & Schofield"):
// τ of free water, SIER2's round-off in three scalars, Table I of the dipole in a field, accuracy against
// cost and the failure step on a grid of h/f, the leapfrog's remainder in both axis orders, and the CPU
// cost per molecule-step. Plain numbers; reports/vzs_section formats and draws them.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"

namespace rotlie::runs {

/// The run sizes of the study.
struct vzs_budget {
  long tau_runs;
  double tau_T_ps;
  long table_runs;
  double table_T_ps;
  long scan_runs;
  double scan_T_ps;
  double roundoff_double_T_ps, roundoff_long_double_T_ps, roundoff_float128_T_ps;
  long roundoff_runs;
  double cost_seconds;  ///< CPU seconds of one timing of the cost table
  int cost_rounds;      ///< interleaved timings per integrator, the least kept
};

/// The report's budget: `quick` for `rotlie report --quick`, else the default.
vzs_budget vzs_budget_for(bool quick);

/// One integrator of the study: shown label, md integrator name, the paper's integrator it stands for ("" if none).
struct vzs_integrator {
  std::string label, name, paper;
  int f = 0;  ///< force evaluations per step
};

/// SIER2's free-water run at h = 1.66 fs in one scalar, and the same ensemble over 10 ps.
struct vzs_roundoff {
  std::string scalar;                 ///< "double", "long double", "float128"
  models::free_water_result run, at10;  ///< for float128, at10 is the run itself
  double eps = 0;                     ///< the scalar's unit round-off ε/2 as a double
  double growth = 0;                  ///< p: slope of log δ against log t over the second half of the run
};

/// Table I: one cell per (h/f, integrator).
struct vzs_table_cell {
  models::mean_error dH, dLz;
};

/// Accuracy against cost of one integrator over vzs_study_result::grid; points only where defined.
struct vzs_scan {
  std::vector<double> dipole_h, dipole_cpu, dipole_error;  ///< h/f, CPU s per ps, ΔH/ΔV (%)
  std::vector<double> free_h, free_cpu, free_rate;         ///< h/f, CPU s per ps, 1/τ (1/ps)
  double last_dipole = 0, last_free = 0;                   ///< largest working h/f before the first failure (0: none)
};

/// Size of the leapfrog's H_R3 for water scaled to I3 = 1 over the canonical momenta.
struct vzs_remainder_size {
  double norm = 0;         ///< Euclidean norm of the coefficients (LV's ‖H_R‖)
  double fluctuation = 0;  ///< canonical rms of H_R3 − ⟨H_R3⟩
  double gradient = 0;     ///< canonical rms of |∇_G H_R3|
};

struct vzs_study_result {
  std::vector<vzs_integrator> integrators;              ///< every row; the first five are Table I's
  std::vector<std::array<models::free_water_result, 2>> tau;  ///< per integrator, at h = 1.66 and 8 fs
  std::vector<vzs_roundoff> roundoff;                   ///< double, long double, float128
  std::array<double, 3> table_h_over_f{4.2, 11, 21};
  std::array<std::vector<vzs_table_cell>, 3> table;     ///< per h/f, per Table I integrator
  std::vector<double> grid;                             ///< h/f of the scan (fs)
  double energy_limit = 10;                             ///< % of ΔV: failure of the dipole
  double tau_limit = 100;                               ///< ps: failure of free water
  std::vector<vzs_scan> scan;                           ///< per integrator
  vzs_remainder_size mrdl_remainder, reversed_remainder;  ///< ABCBA2:ABC and ABCBA2:CBA
  std::vector<double> cost_ns;                          ///< per integrator, CPU ns per molecule-step
};

/// Runs the whole study; `progress` (may be empty) receives a line before each piece.
vzs_study_result vzs_study(const vzs_budget& budget, const std::function<void(const std::string&)>& progress = {});

/// Slope of log δ against log t over the second half of the samples (models::fitted_order).
double growth_exponent(const models::free_water_result& r);

}  // namespace rotlie::runs
