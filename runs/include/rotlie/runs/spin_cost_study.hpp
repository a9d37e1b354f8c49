#pragma once
// The report's sweep of error against CPU time in the spin–orbit scene (spin_orbit_cost.hpp measures
// each point): for each case, SIER4, SIER4 with McLachlan's RS rotor and with the body's best dedicated
// rotor at a list of steps, and Odeint's DOPRI5 and RKF78 at a list of tolerances.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/runs/spin_orbit_cost.hpp"

namespace rotlie::runs {

/// The best dedicated rotor `rotlie best` ranks for a body: R for the near-symmetric Moon and Mercury,
/// for Hyperion the cheapest family's best (N, 9 rotations), which bench/spin_bench measures as the winner.
std::string best_spin_rotor(const std::string& body);

/// One method's points, and the CPU seconds it needs for an error of 1e-9 (cpu_at_error; NaN when not read).
struct spin_cost_curve {
  std::string method;  ///< for Odeint, the family (the tolerances are its points)
  std::vector<spin_cost_point> points;
  double cpu_at_1e9 = 0;
};

struct spin_cost_panel {
  spin_cost_case case_;
  std::vector<spin_cost_curve> curves;  ///< the three splittings, then odeint-dopri5 and odeint-rkf78
};

/// Every spin_cost_cases() case. steps: per orbit (Hyperion's four times finer: its (B − A)/C is about
/// 1000 times the Moon's); tolerances: Odeint's; each point repeated until min_cpu_s of CPU is spent.
/// progress, if given, hears "Spin-orbit: error against CPU time, LABEL" before each case.
std::vector<spin_cost_panel> spin_cost_study(const std::vector<double>& steps, const std::vector<std::string>& tolerances, double min_cpu_s,
                                             const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
