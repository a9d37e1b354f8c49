// Report section "Liquid water at 300 K" (docs/thermostats.md): rigid TIP3P held at 300 K by each
// thermostatted integrator at each step against SIER2-BAOAB at a small step; the temperatures (kinetic
// at the step's end and after the O-step, configurational), V per molecule, g_OO's first peak, D, the
// cost; and which integrator to take at each step. Every number is runs::liquid_water_nvt_study's.
#include <cmath>
#include <sstream>

#include "rotlie/reports/report.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "rotlie/runs/liquid_water_nvt_study.hpp"
#include "rotlie/runs/number_text.hpp"
#include "sections.hpp"

namespace rotlie::reports {
namespace {

std::string pm(const models::mean_error& m, int digits) {
  if (std::isnan(m.mean)) return "–";
  return runs::significant_text(m.mean, digits) + " ± " + runs::significant_text(m.error, 2);
}

void row(std::ostringstream& md, const std::string& name, double h, double hf, const models::liquid_water_nvt_result& r, const std::string& verdict) {
  md << "| " << name << " | " << runs::significant_text(h, 3) << " | " << runs::significant_text(hf, 3) << " | " << pm(r.translational_K, 4) << " | "
     << pm(r.rotational_K, 4) << " | " << pm(r.rotational_after_o_K, 4) << " | " << pm(r.configurational_translational_K, 4) << " | "
     << pm(r.configurational_rotational_K, 4) << " | " << pm(r.potential_per_molecule, 5) << " | " << runs::significant_text(r.rdf_peak_g, 3) << " | "
     << runs::significant_text(r.diffusion, 3) << " | " << runs::significant_text(r.cpu_ms_per_step, 3) << " | " << verdict << " |\n";
}

}  // namespace

report_section liquid_water_nvt_section(const report_options& options) {
  section_writer w(options, "Liquid water at 300 K", "Liquid water at 300 K");
  const auto budget = runs::liquid_water_nvt_budget_for(options.quick, options.full);
  const auto study = runs::liquid_water_nvt_study(budget, [&w](const std::string& line) { w.progress(line); });
  auto& md = w.md;
  md << budget.molecules << " rigid TIP3P molecules (rotlie's smooth 11 Å molecular cutoff, 0.9973 g/cm³) equilibrated at 300 K, then held "
     << "at 300 K by each integrator for " << runs::significant_text(budget.run_ps, 3)
     << " ps per run (the first fifth settling; Langevin friction 1/ps, chains' period 0.1 ps; `rotlie md --scene liquid-water "
        "--integrator NAME --temperature 300`). Each value is the mean over the rest ± its standard error from 10 blocks. T_trans and T_rot "
        "are the kinetic temperatures at the step's end, T_rot(O) right after the O-step (BAOAB's mid-step: the thermostat's own); "
        "T_conf the configurational temperatures of the centres and the rotations (⟨Σ|F|²⟩/⟨∇²V⟩, ⟨Σ|τ|²⟩/⟨Σ X²V⟩ with Hutchinson's "
        "estimator); D in 10⁻⁵ cm²/s from the centres' mean squared displacement (Langevin's friction slows it); CPU ms per step on two threads. "
        "The reference is SIER2-BAOAB at "
     << runs::significant_text(budget.reference_h_fs, 3) << " fs. A run *agrees* when V and both T_conf are within 3 combined standard "
        "errors of the reference's.\n\n"
     << "| integrator | h (fs) | h/f (fs) | T_trans (K) | T_rot (K) | T_rot(O) (K) | T_conf centres (K) | T_conf rotations (K) | V/N (kcal/mol) | "
        "g_OO peak | D | CPU ms | |\n|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|:--|\n";
  row(md, "SIER2-BAOAB (reference)", budget.reference_h_fs, budget.reference_h_fs, study.reference, "");
  for (const auto& p : study.points) {
    if (p.failed) {
      md << "| " << p.integrator << " | " << runs::significant_text(p.h_fs, 3) << " | " << runs::significant_text(p.h_over_f_fs, 3)
         << " | failed: " << p.failure << " | | | | | | | | | |\n";
      continue;
    }
    const std::string z = "V: " + runs::significant_text(p.potential_z, 2) + "σ, T_conf: " + runs::significant_text(p.configurational_z, 2) + "σ";
    row(md, p.integrator, p.h_fs, p.h_over_f_fs, p.result, study.judged ? (p.agrees ? "agrees (" : "differs (") + z + ")" : z);
  }
  if (!study.judged)
    md << "\nThese runs (" << runs::significant_text(budget.run_ps, 3) << " ps) are too short to judge which integrator agrees: their "
       << "blocks are shorter than V's correlation time, so the standard errors above understate the noise (`rotlie report` without "
          "--quick runs " << runs::significant_text(runs::min_judged_run_ps, 2) << " ps and more).\n";
  else
    md << "\n**Which integrator at which step** (the cheapest per step among those that agree; this run's numbers):\n\n"
       << "| h/f (fs) | take | CPU ms per step |\n|--:|:--|--:|\n";
  for (const auto& c : study.judged ? study.choices : std::vector<runs::liquid_water_nvt_choice>{})
    md << "| " << runs::significant_text(c.h_over_f_fs, 3) << " | " << (c.integrator.empty() ? "none agrees" : c.integrator) << " | "
       << (c.integrator.empty() ? "–" : runs::significant_text(c.cpu_ms_per_step, 3)) << " |\n";
  md << "\nThe runs are short: a difference of a few tenths of a kelvin or hundredths of a kcal/mol is within the noise, and the verdicts "
        "at the largest steps are the ones to read. `rotlie report --full` runs 512 molecules for 20 ps at h/f up to 8 fs. LAMMPS's "
        "fixes side by side (rigid/nvt/small, rigid/small langevin and the rigid/sier* thermostats) are in lammps/README.md "
        "(lammps/bench/thermostat_sweep.py).\n\n";
  return w.finish();
}

}  // namespace rotlie::reports
