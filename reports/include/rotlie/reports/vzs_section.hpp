#pragma once
// Report section "van Zon & Schofield": the free-water orientation error time τ (section V.A), Table I
// for the dipole in a field (section V.B), accuracy against cost and the failure step of every
// integrator, each beside the paper's values with the discrepancies explained.
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

report_section vzs_section(const report_options& options);

}  // namespace rotlie::reports
