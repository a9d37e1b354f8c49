#pragma once
// The report's long runs of the spin–orbit scene (spin_orbit_drift.hpp runs each track): for the Moon and
// Mercury, the attitude error after 10², 10³, … orbits of SIER4, SIER4 with the R and the RS rotor, and
// RKF78 in double at the tolerance of equal CPU, against RKF78 in long double at 1e-18.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/runs/spin_orbit_drift.hpp"

namespace rotlie::runs {

struct spin_drift_row {
  std::string method;
  std::vector<double> error;  ///< rad, at each checkpoint
  double cpu_s = 0;           ///< stepping CPU seconds of the whole run
};

struct spin_drift_table {
  spin_drift_case case_;
  std::vector<spin_drift_row> rows;
};

struct spin_drift_result {
  std::vector<long> checkpoints;  ///< 100, 1000, … up to `last` orbits
  std::vector<spin_drift_table> tables;
};

/// Every spin_drift_cases() case but Hyperion (4.2 n needs 400 steps an orbit: bench/spin_drift_bench's).
/// progress, if given, hears "Spin-orbit: long runs, LABEL" before each case.
spin_drift_result spin_drift_study(long last, const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
