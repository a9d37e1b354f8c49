#pragma once
// Do the maps tell the truth? (issue 14, item 6.) For one body, the best N and P integrators by
// analytic remainder ‖H_R5‖ (the maps' choice, LV section 5) measured with the numeric protocol
// (LV section 4.1) against RS4 S5 McLachlan at its best MEASURED permutation, at equal h/C and at
// equal CPU time, next to two cheap predictors of the measured ratio computed from H_R5 alone
// (models/remainder_predictor.hpp). Ratios > 1: the family's integrator beats the reference.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/remainder_predictor.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::runs {

/// The protocol's step levels for the study: h = 2^-5 … 2^-9, constants fitted on the 3 finest.
inline constexpr int truth_min_level = 5, truth_max_level = 9;

/// H_R5 of a solution at its body (scaled to I3 = 1) as plain data for the numeric side.
std::vector<models::remainder_term> remainder_terms(const solver::dedicated_solution& s,
                                                    const lie::moments_of_inertia& body);
/// H_R5 of a reference scheme (base name) at a permutation, body scaled to I3 = 1.
std::vector<models::remainder_term> reference_remainder_terms(const std::string& base, const std::string& permutation,
                                                              const lie::moments_of_inertia& body);
/// The predictor at the protocol's initial state (G = (1, 1, 1), T = 1), body scaled to I3 = 1.
models::remainder_prediction predict_protocol_error(const lie::moments_of_inertia& body,
                                                    const std::vector<models::remainder_term>& h5);

struct family_truth {
  std::string family;
  std::optional<std::string> best;  ///< SCHEME:PERM:LABEL, absent when the family has no solution here
  double analytic_ratio = 0;        ///< R_M / R_best × (12/C)^4, R_M at the reference's best analytic permutation
  double measured_ratio_h = 0;      ///< measured constants at equal h/C
  double measured_ratio_cpu = 0;    ///< at equal measured CPU time
  double predicted_ratio = 0;       ///< transported remainder (reference at its best predicted permutation)
  double gradient_ratio = 0;        ///< mean |∇H_R5| along the motion, same normalisation
  double slope = 0;                 ///< the family scheme's fitted order
  double predicted_constant = 0, measured_constant = 0;  ///< error / (h/C)^4: predicted and measured
};

struct body_truth {
  lie::moments_of_inertia body;  ///< I3 = 1
  std::string reference;         ///< RS4-S5-McLachlan:<best measured permutation>
  double reference_slope = 0;
  std::vector<family_truth> families;  ///< "N", "P" in that order
};

/// Process CPU seconds per step of the double stepper (the fastest of 5 runs of ≥ 10 ms each).
double cpu_seconds_per_step(const schemes::scheme_table& table, const lie::moments_of_inertia& body);

/// Solves each family exactly at the body and measures (a few seconds for P).
body_truth measure_body_truth(const lie::moments_of_inertia& body, const std::vector<std::string>& families);

/// The study's bodies: the asymmetric grid bodies of K (issue 14's grid), then water.
std::vector<lie::moments_of_inertia> truth_bodies(int K);

/// Spearman's rank correlation (average ranks for ties); NaN for fewer than 3 pairs.
double spearman(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace rotlie::runs
