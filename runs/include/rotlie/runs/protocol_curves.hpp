#pragma once
// The paper's numeric protocol (LV section 4.1) applied to sets of schemes for one body:
// G(0) = (1, 1, 1), identity attitude, T = 1, h = 2^-i; the mean attitude error per step in long
// double (double round-off would flatten the finest 4th-order points), and the CPU time per step
// measured on the double stepper, the one a user would run.
#include <string>
#include <utility>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/scheme_table.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

struct curve_point {
  double h = 0, h_over_cost = 0, error = 0, cpu_seconds = 0;  ///< cpu: per unit of simulated time
};

struct scheme_curve {
  std::string name;
  int cost = 0;   ///< rotations per step (C / C0)
  int order = 0;  ///< declared
  std::vector<curve_point> points;  ///< coarse to fine
  double seconds_per_step = 0;      ///< measured, double
  double slope = 0;                 ///< fitted over the three finest points
  /// error / (h/C)^order averaged over the three finest points: two schemes of the same order
  /// compare at equal reduced step by the ratio of their constants (the paper's h⁴ scaling).
  double constant = 0;
};

class protocol_runner {
 public:
  /// With time_steps false the CPU columns stay 0 (for choosing a permutation quickly).
  protocol_runner(const lie::moments_of_inertia& body, int min_level, int max_level, bool time_steps = true);
  scheme_curve run(const schemes::scheme_table& table) const;
  /// The permutation of a reference scheme (base name such as RSR4-SS3-Yoshida) with the smallest constant.
  scheme_curve best_permutation(const std::string& base_name) const;

 private:
  std::string inertia_;  ///< the body's exact moments as text, read into each scalar once
  models::vec3<long double> I_;
  models::body_state<long double> initial_;
  models::exact_samples<long double> exact_;
  int min_level_, max_level_;
  bool time_steps_;
};

/// How many times more accurate `better` is than `worse` at equal reduced step h/C.
double ratio_at_equal_reduced_step(const scheme_curve& worse, const scheme_curve& better);
/// The same at equal measured CPU time per unit of simulated time.
double ratio_at_equal_cpu_time(const scheme_curve& worse, const scheme_curve& better);

/// A curve's law error = constant (h/C)^order and its fitted slope (models::fitted_order), over its three
/// finest points, as protocol_runner::run fits it: for curves read back from a report's files.
struct finest_fit {
  double constant = 0, slope = 0;
};
/// `points` are (h/C, error) in any order; throws std::runtime_error with fewer than three.
finest_fit fit_finest(std::vector<std::pair<double, double>> points, int order);

/// The solution named scheme/perm/label in a solver result; throws std::runtime_error if absent.
const solver::dedicated_solution& find_solution(const solver::family_result& r, const std::string& scheme,
                                                const std::string& perm, int label);

}  // namespace rotlie::runs
