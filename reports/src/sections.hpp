#pragma once
// The writers of the report's sections (one file each in reports/src); what each draws and its key
// are in report_sections() (report.cpp), the one list of sections.
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

using section_function = report_section(const report_options&);
section_function lie_algebra_section, remainder_section, dedicated_section, accuracy_section, stability_section, exact_flow_section,
    maps_section, maps_truth_section, beyond_section, two_parameter_section, spin_orbit_section, binary_section, audit_section, liquid_water_nvt_section;

}  // namespace rotlie::reports
