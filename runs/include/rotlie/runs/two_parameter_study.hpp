#pragma once
// The measurements of the report's section "Beyond the paper: two free parameters at order 4": the
// searches of the Q (13-stage ABC) and QRS (11-stage RS) families for water, and the protocol runs of
// their best certified schemes against P1 BAC (5) and RS4-S5-McLachlan:CBA, then of every polished
// system. Plain numbers; reports/two_parameter_section formats and draws them.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/solver/two_parameter.hpp"

namespace rotlie::runs {

/// Digits of the polished minima.
inline constexpr int two_parameter_study_digits = 45;

/// One polished system measured against P1 BAC (5) at equal h/C.
struct two_parameter_screened {
  std::string name;
  double remainder = 0;  ///< ‖H_R5‖
  int cost = 0;          ///< C/C0
  double ratio = 0;      ///< P1's error over this one's at equal h/C
};

/// A system's coefficients in stage order, each name once: the part letter after the permutation, the
/// name (a1, b2, …), the value as written.
struct two_parameter_coefficient {
  char letter = 'A';
  std::string name;
  cln::cl_RA value;
};
struct two_parameter_listing {
  std::string permuted_word;
  std::vector<two_parameter_coefficient> coefficients;
};
two_parameter_listing two_parameter_coefficients(const solver::two_parameter_entry& e);

struct two_parameter_study_result {
  int abc_starts = 0, rs_starts = 0;  ///< per system
  std::size_t abc_words = 0;          ///< 13-stage ABC palindromes
  solver::two_parameter_result q, qrs;
  /// The comparison (only when both families have a certified minimum): the best of each.
  std::optional<solver::two_parameter_entry> best_q, best_rs;
  std::string p1_name;
  double p1_remainder = 0;  ///< ‖H_R5‖ of P1 BAC (5)
  int max_level = 0;        ///< the protocol's finest h = 2^-max_level
  /// P1 BAC (5), RS4-S5-McLachlan:CBA, the best Q, the best QRS
  std::vector<scheme_curve> curves;
  std::vector<double> remainders;  ///< ‖H_R5‖ per curve, 0 where not known
  std::vector<two_parameter_screened> screened;  ///< every polished system, Q then QRS
};

/// Runs the study for water; `quick` for fewer starts and a shorter protocol.
two_parameter_study_result two_parameter_study(bool quick, const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
