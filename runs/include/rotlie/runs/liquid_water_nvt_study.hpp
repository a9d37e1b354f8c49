#pragma once
// Liquid water at 300 K (the report's section "Liquid water at 300 K", docs/thermostats.md): rigid TIP3P
// (rotlie's smooth molecular cutoff) from one equilibrated start, run by each thermostatted integrator at
// each step, and by SIER2-BAOAB at a small step as the reference; per run the kinetic temperatures (at
// the step's end and, for Langevin, right after the O-step), the configurational temperatures, the
// potential energy per molecule, g_OO's first peak, the diffusion coefficient and the CPU per step; and,
// from those, which integrator to take at each step: the cheapest whose configurational averages agree
// with the reference's within their statistical errors. Plain numbers; reports/ formats them.
#include <functional>
#include <string>
#include <vector>

#include "rotlie/models/scenes/liquid_water_nvt.hpp"

namespace rotlie::runs {

struct liquid_water_nvt_budget {
  long molecules;
  double run_ps, equilibration_ps, reference_h_fs;
  std::vector<std::string> integrators;  ///< thermostatted names (runs/methods.hpp)
  std::vector<double> h_over_f_fs;       ///< the steps, per force evaluation (SIER4's h is 4 times)
};

/// quick: 365 molecules, 1 ps per run; default: 365 molecules, 4 ps; full: 512 molecules, 20 ps, h/f to 8 fs.
liquid_water_nvt_budget liquid_water_nvt_budget_for(bool quick, bool full);

struct liquid_water_nvt_point {
  std::string integrator;
  double h_fs = 0, h_over_f_fs = 0;
  bool failed = false;
  std::string failure;
  models::liquid_water_nvt_result result;
  /// |V − V_ref| and |T_conf − T_conf,ref| (centres and rotations) over their combined standard errors
  double potential_z = 0, configurational_z = 0;
  bool agrees = false;  ///< every z within 3
};

struct liquid_water_nvt_choice {
  double h_over_f_fs = 0;
  std::string integrator;  ///< empty: none agrees at this step
  double cpu_ms_per_step = 0;
};

/// Runs shorter than this are not judged: their 10 blocks are shorter than V's correlation time (about a
/// picosecond), so the blocks' standard errors understate the noise and a verdict would be the noise's.
inline constexpr double min_judged_run_ps = 4;

struct liquid_water_nvt_study_result {
  liquid_water_nvt_budget budget;
  bool judged = false;  ///< the runs are long enough for the agree/differ verdicts (min_judged_run_ps)
  models::liquid_water_nvt_result reference;
  std::vector<liquid_water_nvt_point> points;
  std::vector<liquid_water_nvt_choice> choices;  ///< at each h/f: the cheapest integrator that agrees
};

liquid_water_nvt_study_result liquid_water_nvt_study(const liquid_water_nvt_budget& budget, const std::function<void(const std::string&)>& say);

}  // namespace rotlie::runs
