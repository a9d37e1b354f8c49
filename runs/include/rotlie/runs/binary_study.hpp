#pragma once
// The measurements behind the report's section "Binary asteroid" (docs/binary.md): the Didymos
// system's observables (mutual orbit period, the secondary's libration, the primary's spin), the
// period change of an impulsive Δv on the secondary (DART), and error against CPU time for every
// integrator at orders 2 and 4, and the cheapest splitting at a given error.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/runs/binary_observables.hpp"
#include "rotlie/runs/binary_run.hpp"

namespace rotlie::runs {

/// Runs `setup` (its every is set to `every`) and reads the observables.
binary_observables observe_binary(binary_setup setup, long every);

/// The start of `setup` with Δv (km/s) added to the secondary's velocity along −v (DART struck
/// Dimorphos against its orbital motion): the relative velocity changes by Δv.
binary_setup with_impulse(binary_setup setup, double dv);

/// One run of the cost study.
struct binary_cost_row {
  std::string integrator;
  int order = 2;
  double h = 0;  ///< s (an adaptive method: its checks' spacing)
  long steps = 0, evaluations = 0;
  double cpu_s = 0;
  double error = 0;  ///< max(|Δr|/|r|, the attitude angles of both bodies, rad) against the reference
  double energy_error = 0, angular_momentum_error = 0;
  bool unstable = false;
};

struct binary_cost_plan {
  std::string system = "didymos";
  std::vector<int> orders{2, 4};
  double T = 0;  ///< s, a whole number of every step below
  std::vector<std::string> integrators;  ///< fixed-step methods, each at every step of `steps`
  std::vector<double> steps;
  std::vector<std::string> adaptive;     ///< odeint-…:TOL, run once each with checks every `adaptive_h`
  double adaptive_h = 0;
  std::string reference = "KEPLER4";     ///< the reference integrator and its step
  double reference_h = 0;
};

/// The rows, and for each order the reference's own error estimate (the reference against a second
/// one at half its step).
struct binary_cost_result {
  std::vector<binary_cost_row> rows;
  std::vector<double> reference_error;  ///< per order
};

binary_cost_result binary_cost_study(const binary_cost_plan& plan, const std::function<void(const std::string&)>& progress = {});

/// The distance of two final states as binary_cost_row::error measures it.
double binary_state_error(const models::binary_state<double>& x, const models::binary_state<double>& reference);

/// At the error one run of a cost sweep reached (`anchor` at step h, at one order): the cheapest TV
/// splitting of the same order (Odeint, RK4 and the LGVI left out) that reaches it without going unstable.
struct cheapest_splitting {
  binary_cost_row anchor;
  bool found = false;    ///< some splitting step of the sweep reaches the anchor's error
  binary_cost_row best;  ///< when found
  bool less_cpu = false; ///< the splitting needs no more CPU than the anchor
  double cpu_ratio = 0;  ///< the larger CPU time over the smaller (≥ 1), when found
};

/// Empty when the sweep has no such anchor run.
std::optional<cheapest_splitting> cheapest_splitting_at(const binary_cost_result& result, int order, const std::string& anchor, double h);

}  // namespace rotlie::runs
