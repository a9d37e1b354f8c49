#include "rotlie/runs/liquid_water_nvt_study.hpp"

#include <cmath>
#include <stdexcept>

#include "liquid_water_run.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/number_text.hpp"

namespace rotlie::runs {

liquid_water_nvt_budget liquid_water_nvt_budget_for(bool quick, bool full) {
  if (quick) return {365, 1, 2, 1, {"SIER2-NHC", "SIER2-BAOAB"}, {2, 4}};
  if (full)
    return {512, 20, 10, 0.5, {"MRDL-NHC", "SIER2-NHC", "SIER4-NHC", "MRDL-BAOAB", "SIER2-BAOAB", "SIER2-OBABO", "SIER4-BAOAB"}, {1, 2, 4, 6, 8}};
  return {365, 4, 10, 0.5, {"MRDL-NHC", "SIER2-NHC", "MRDL-BAOAB", "SIER2-BAOAB", "SIER4-BAOAB"}, {1, 2, 4}};
}

namespace {

double z_of(const models::mean_error& a, const models::mean_error& b) {
  const double e = std::hypot(a.error, b.error);
  return e > 0 ? std::abs(a.mean - b.mean) / e : std::nan("");
}

}  // namespace

liquid_water_nvt_study_result liquid_water_nvt_study(const liquid_water_nvt_budget& budget, const std::function<void(const std::string&)>& say) {
  liquid_water_nvt_study_result out;
  out.budget = budget;
  out.judged = budget.run_ps >= min_judged_run_ps;
  models::liquid_water_run_options o;
  o.molecules = budget.molecules;
  o.threads = 2;
  o.kelvin = 300;
  o.equilibration_ps = budget.equilibration_ps;
  o.T_ps = budget.run_ps;
  auto show = [&say](const std::string&) {};  // the runs' own lines are too many for the report's progress
  if (say) say("equilibrating " + std::to_string(budget.molecules) + " molecules");
  const auto start = models::liquid_water_start(o, show);
  models::liquid_water_nvt_options nvt;
  nvt.kelvin = 300;
  auto run = [&](const std::string& name, double h) {
    o.integrator = method_named(name, method_system::md).splitting;
    o.h_fs = h;
    return liquid_water_nvt_run(o, nvt, start, show);
  };
  if (say) say("the reference, SIER2-BAOAB at " + significant_text(budget.reference_h_fs, 3) + " fs");
  out.reference = run("SIER2-BAOAB", budget.reference_h_fs);
  for (const double hf : budget.h_over_f_fs) {
    liquid_water_nvt_choice choice{hf, "", 0};
    for (const auto& name : budget.integrators) {
      liquid_water_nvt_point p;
      p.integrator = name;
      p.h_over_f_fs = hf;
      p.h_fs = hf * method_named(name, method_system::md).splitting.f;
      if (say) say(name + " at h = " + significant_text(p.h_fs, 3) + " fs");
      try {
        p.result = run(name, p.h_fs);
        const auto& r = p.result;
        p.potential_z = z_of(r.potential_per_molecule, out.reference.potential_per_molecule);
        p.configurational_z = std::max(z_of(r.configurational_translational_K, out.reference.configurational_translational_K),
                                       z_of(r.configurational_rotational_K, out.reference.configurational_rotational_K));
        p.agrees = out.judged && p.potential_z <= 3 && p.configurational_z <= 3;
        if (p.agrees && (choice.integrator.empty() || r.cpu_ms_per_step < choice.cpu_ms_per_step))
          choice = {hf, name, r.cpu_ms_per_step};
      } catch (const std::runtime_error& e) {
        p.failed = true;
        p.failure = e.what();
      }
      out.points.push_back(std::move(p));
    }
    out.choices.push_back(choice);
  }
  return out;
}

}  // namespace rotlie::runs
