#pragma once
// Report section "In LAMMPS": rotlie's fix styles inside LAMMPS (lammps/), rendered from the CSVs that
// lammps/bench/lammps_bench.py wrote into <out_dir>/lammps-bench/ (the report does not run LAMMPS).
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

report_section lammps_section(const report_options& options);

}  // namespace rotlie::reports
