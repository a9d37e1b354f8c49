// The measurements of van Zon & Schofield's section V.C on 512 TIP3P molecules (see liquid_water_study.hpp).
#include "rotlie/runs/liquid_water_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <stdexcept>

#include "rotlie/models/order_fit.hpp"
#include "rotlie/models/scenes/lammps_water_io.hpp"
#include "rotlie/models/scenes/water_model.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "liquid_water_run.hpp"

namespace rotlie::runs {

namespace {

struct step_sweep {
  std::string integrator;
  std::vector<double> h;
  const schemes::scheme_table* rotor = nullptr;  ///< a dedicated rotor's table, solved for TIP3P
};

// The dedicated free rotors for the TIP3P body (its exact moments text): the best-ranked N and P
// solutions of the solver for this body, N2 BAC (2) and P1 BAC (5).
std::map<std::string, schemes::scheme_table> water_dedicated_rotors() {
  const auto body = lie::parse_moments(models::tip3p_body_text());
  std::map<std::string, schemes::scheme_table> tables;
  for (const char* name : {"N2:BAC:2", "P1:BAC:5"}) tables.emplace(name, scheme_named(name, body));
  return tables;
}

}  // namespace

double liquid_water_slope(const liquid_water_sweep& sweep, double diverged_percent, double x_max) {
  // coarse to fine, as the one fit takes its points
  std::vector<models::protocol_point> points;
  for (auto p = sweep.points.rbegin(); p != sweep.points.rend(); ++p) {
    if (p->failed || !(p->result.ratio_mean < diverged_percent)) continue;
    const double hf = p->h_fs / p->result.f;
    if (hf <= x_max) points.push_back({hf, hf, p->result.ratio_mean, 0});
  }
  models::fit_rule all;
  all.margin = 0;
  return models::fitted_order(points, all);
}

liquid_water_study_result liquid_water_study(const liquid_water_budget& b, bool quick, bool full,
                                             const std::function<void(const std::string&)>& progress) {
  const auto say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  liquid_water_study_result out;
  out.box_A = models::liquid_water_box(512, 0.9973);
  for (std::size_t k = 0; k < 3; ++k) out.moments_text[k] = models::tip3p_moments_text[k];
  models::liquid_water_run_options o;
  o.threads = 2;
  o.runs = b.runs;
  o.T_ps = b.run_ps;
  o.equilibration_ps = b.equilibration_ps;
  say("equilibration");
  const auto start = models::liquid_water_start(o, say);
  std::vector<step_sweep> sweeps;
  sweeps.push_back({"SIER2", quick ? std::vector<double>{1, 2, 4, 7} : std::vector<double>{0.5, 1, 2, 4, 7, 10}});
  sweeps.push_back({"SIER4", quick ? std::vector<double>{4, 8, 16, 28} : std::vector<double>{1, 2, 4, 8, 16, 28, 40}});
  sweeps.push_back({"MRDL", quick ? std::vector<double>{2, 7} : std::vector<double>{1, 2, 4, 7, 10}});
  sweeps.push_back({"SEJ4", quick ? std::vector<double>{2, 7} : std::vector<double>{1, 2, 4, 7}});
  if (!quick) sweeps.push_back({"SIER2/RS4-S5-McLachlan:CBA", {1, 2, 4, 7}});
  say("dedicated rotors for the TIP3P body");
  const auto dedicated = water_dedicated_rotors();
  // full: the paper's statistics, the same steps as SIER2 and SIER4
  sweeps.push_back({"SIER2/N2:BAC:2", quick ? std::vector<double>{2, 7} : full ? sweeps[0].h : std::vector<double>{1, 2, 4, 7},
                    &dedicated.at("N2:BAC:2")});
  sweeps.push_back({"SIER4/P1:BAC:5", quick ? std::vector<double>{8, 28} : full ? sweeps[1].h : std::vector<double>{4, 8, 16, 28},
                    &dedicated.at("P1:BAC:5")});
  for (const auto& sw : sweeps) {
    auto& measured = out.sweeps.emplace_back();
    measured.integrator = sw.integrator;
    for (double h : sw.h) {
      o.integrator = method_named(sw.integrator, method_system::md).splitting;  // the study's own names; X solved above
      o.rotor_table = sw.rotor;
      o.h_fs = h;
      o.T_ps = std::max(b.run_ps, 10 * h / 1000);  // at least 10 steps per run
      say(sw.integrator + " at h = " + significant_text(h, 3) + " fs");
      auto& point = measured.points.emplace_back();
      point.h_fs = h, point.runs = o.runs, point.T_ps = o.T_ps;
      try {
        point.result = liquid_water_runs(o, start, {});
        point.f = point.result.f;
        if (sw.integrator == "SIER2" && h == 1 && point.result.ratio_mean < out.diverged_percent)
          out.v_per_molecule = point.result.potential_per_molecule, out.temperature = point.result.temperature;
      } catch (const std::runtime_error& e) {
        point.failed = true;
        point.failure = e.what();
        point.f = o.integrator.f;
      }
    }
  }

  // physical sanity: g_OO(r)
  say("g(r)");
  out.g_OO = models::sample_oxygen_rdf(o, start, std::lround(b.rdf_ps * 1000), 1.0, 10);

  // LAMMPS side by side
  models::liquid_water_options<double> dsf;
  dsf.box = models::liquid_water_box(512, 0.9973);
  dsf.interaction = models::water_interaction::lammps_dsf;
  dsf.threads = 2;
  const models::liquid_water<double> w(models::tip3p<double>(), dsf);
  std::vector<models::vec3<double>> mine, theirs;
  say("LAMMPS single point");
  out.V_rotlie = w.evaluate_sites(start.bodies, mine);
  out.V_lammps = models::lammps_single_point(w, start.bodies, theirs);
  out.lammps_ran = theirs.size() == mine.size();
  if (!out.lammps_ran) return out;
  for (std::size_t k = 0; k < mine.size(); ++k)
    for (int d = 0; d < 3; ++d)
      out.worst_force = std::max(out.worst_force, std::abs(mine[k][d] - theirs[k][d])),
      out.force_scale = std::max(out.force_scale, std::abs(theirs[k][d]));
  for (int threads : {1, 2}) {
    models::liquid_water_options<double> d1 = dsf;
    d1.threads = threads;
    const models::liquid_water<double> wt(models::tip3p<double>(), d1);
    say("rotlie DSF, " + std::to_string(threads) + " thread(s)");
    models::with_md_integrator(method_named("SIER2/ABCBA2:ABC", method_system::md).splitting, nullptr, models::tip3p<double>().mass,
                               models::tip3p<double>().moments, wt, [&](const auto& m) {
                                 auto x = start;
                                 x.forces_current = false;
                                 const auto& sys = m.system();
                                 double es = 0, ess = 0, vs = 0, vss = 0;
                                 const double e0 = sys.energy(x), v0 = sys.potential_energy(x);
                                 const std::clock_t c0 = std::clock();
                                 const auto t0 = std::chrono::steady_clock::now();
                                 for (long k = 0; k < b.lammps_steps; ++k) {
                                   m.step(x, 1.0);
                                   const double V = sys.potential_energy(x), E = V + sys.kinetic_energy(x);
                                   es += E - e0, ess += (E - e0) * (E - e0), vs += V - v0, vss += (V - v0) * (V - v0);
                                 }
                                 const double n = static_cast<double>(b.lammps_steps);
                                 liquid_water_timing t;
                                 t.threads = threads, t.ran = true;
                                 t.wall_ms = 1000 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n;
                                 t.cpu_ms = 1000 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / n;
                                 t.ratio_percent = 100 * std::sqrt(ess / n - es * es / (n * n)) / std::sqrt(vss / n - vs * vs / (n * n));
                                 out.rotlie_timings.push_back(t);
                                 return 0;
                               });
  }
  for (int procs : {1, 2}) {
    say("LAMMPS, " + std::to_string(procs) + " rank(s)");
    const auto r = models::run_lammps_rigid_nve(w, start.bodies, b.lammps_steps, 1.0, procs);
    liquid_water_timing t;
    t.threads = procs, t.ran = r.ran;
    // LAMMPS's CPU time is its wall time times its reported CPU use
    t.wall_ms = r.wall_ms, t.cpu_ms = r.wall_ms * r.cpu_percent / 100 * procs, t.ratio_percent = r.ratio_percent;
    out.lammps_timings.push_back(t);
  }
  return out;
}

}  // namespace rotlie::runs
