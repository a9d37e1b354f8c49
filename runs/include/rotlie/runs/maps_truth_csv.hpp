#pragma once
// The maps-truth study's rows as CSV (maps-truth/measured-ratios.csv): one writer for the two
// producers, the report's own run and the sharded bench/maps_truth_study, whose parts the report
// reads back (--maps DIR) and checks against this header.
#include <string>

#include "rotlie/runs/maps_truth.hpp"

namespace rotlie::runs {

/// The CSV contract: I1,I2,I3,family,best,analytic_ratio,measured_ratio_h,measured_ratio_cpu, then
/// predicted_ratio,gradient_ratio,slope,predicted_constant,measured_constant,reference.
std::string truth_csv_header();
/// One row per family with a solution at the body (none measured otherwise).
std::string truth_csv_rows(const body_truth& b);

}  // namespace rotlie::runs
