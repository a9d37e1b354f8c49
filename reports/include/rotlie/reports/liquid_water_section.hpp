#pragma once
// Report section "Liquid water" (vZS section V.C, Fig. 1, extended): 512 TIP3P molecules, the
// energy fluctuation of every integrator against h/f and against CPU time, where each fails,
// the O–O radial distribution function and energy per molecule against the model's published
// values, and rotlie side by side with LAMMPS (skipped where `lmp` is missing).
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

/// The stated default budget (quick: smaller still): one run per point, 0.25 ps (quick 0.1 ps).
report_section liquid_water_section(const report_options& options);

/// The paper's statistics: nine 1-ps runs per point (about half an hour on one core; `slow`).
report_section liquid_water_section_full(const report_options& options);

}  // namespace rotlie::reports
