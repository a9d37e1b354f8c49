// Report section "Liquid water" (see liquid_water_section.hpp).
#include "rotlie/reports/liquid_water_section.hpp"

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report_csv_reader.hpp"
#include "rotlie/runs/liquid_water_study.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/shipped_data.hpp"

namespace rotlie::reports {

namespace {

struct budget {
  runs::liquid_water_budget sizes;
  std::string words;
};

// Fig. 1 at the paper's statistics from the shipped full run (data/vzs-fig1), beside this run's own:
// the chart of ΔE/ΔV against h/f and the table with the standard errors over the nine runs.
std::string shipped_fig1(const report_options& options, const std::filesystem::path& file,
                         std::vector<std::filesystem::path>& files) {
  const auto t = read_csv(file);
  if (!t) return "";
  const auto col = [&](const char* name) {
    const auto c = t->column(name);
    if (!c) throw std::runtime_error(file.string() + " has no column " + name);
    return *c;
  };
  const std::size_t who = col("integrator"), f = col("f"), h = col("h_fs"), hf = col("h_over_f_fs"), runs = col("runs"),
                    ratio = col("dE_over_dV_percent"), error = col("standard_error_percent"), diverged = col("diverged");
  chart c;
  c.title = "Liquid water (512 TIP3P), the paper's statistics (shipped full run)";
  c.x_label = "h/f (fs)";
  c.y_label = "ΔE/ΔV (%)";
  c.horizontal_line = 100;
  c.horizontal_label = "100 %: stable range ends";
  std::map<std::string, std::size_t> series_of;
  chart_series gone{"diverged (≥ 100 %)", {}, {}, true};
  gone.colour = "#000000", gone.point_type = 2, gone.point_size = 1.5;
  std::ostringstream table;
  table << "| integrator | f | h (fs) | runs | ΔE/ΔV (%) | ± (standard error) |\n|:--|--:|--:|--:|--:|--:|\n";
  for (const auto& row : t->rows) {
    const bool out = row.at(diverged) == "1";
    table << "| " << row.at(who) << " | " << row.at(f) << " | " << row.at(h) << " | " << row.at(runs) << " | "
          << (out ? std::string("diverged") : runs::significant_text(std::stod(row.at(ratio)), 3)) << " | "
          << (out || row.at(error).empty() || row.at(error) == "nan" ? std::string() : runs::significant_text(std::stod(row.at(error)), 2))
          << " |\n";
    if (out) {
      gone.x.push_back(std::stod(row.at(hf))), gone.y.push_back(100);
      continue;
    }
    auto [it, fresh] = series_of.try_emplace(row.at(who), c.series.size());
    if (fresh) c.series.push_back({row.at(who), {}, {}, false});
    c.series[it->second].x.push_back(std::stod(row.at(hf)));
    c.series[it->second].y.push_back(std::stod(row.at(ratio)));
  }
  if (!gone.x.empty()) c.series.push_back(gone);
  const auto written = write_chart(options.out_dir, "liquid_water_fig1_full", c);
  files.insert(files.end(), written.written.begin(), written.written.end());
  return "### Fig. 1 at the paper's statistics (shipped data)\n\nThe full section's run (`rotlie report --full --sections "
         "liquid-water`: nine 1-ps runs per point after 10 ps of equilibration), shipped as data/vzs-fig1/" +
         file.filename().string() + " with the command and commit that made it (data/README.md).\n\n" +
         chart_markdown(written, "liquid_water_fig1_full", "vZS Fig. 1 with the paper's nine 1-ps runs per point.") + "\n" +
         table.str() + "\n";
}

report_section section(const report_options& options, const budget& b) {
  report_section s;
  s.title = "Liquid water";
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress("Liquid water: " + line);
  };
  const auto study = runs::liquid_water_study(b.sizes, options.quick, options.full, say);
  std::ostringstream md, table, points;
  // every measured point with its statistics, the data behind Fig. 1 (and what data/vzs-fig1 ships)
  points << std::setprecision(17)
         << "integrator,f,h_fs,h_over_f_fs,runs,run_ps,dE_over_dV_percent,standard_error_percent,cpu_ms_per_step,"
            "cpu_ms_per_ps,V_per_molecule,temperature_K,drift_per_ps_per_molecule,diverged\n";
  table << "| integrator | f | h (fs) | h/f (fs) | ΔE/ΔV (%) | ± | wall ms/step | CPU ms/step | CPU ms per ps | V/N (kcal/mol) | T (K) | drift (kcal/mol/ps per molecule) |\n"
           "|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  chart fig1, cpu;
  fig1.title = "Liquid water (512 TIP3P): rms energy fluctuation over rms potential fluctuation";
  fig1.x_label = "h/f (fs)";
  fig1.y_label = "ΔE/ΔV (%)";
  cpu.title = "Liquid water: accuracy against cost";
  cpu.x_label = "measured CPU time per simulated ps (ms, both threads)";
  cpu.y_label = "ΔE/ΔV (%)";
  std::ostringstream slopes, failures;
  // A run whose energy error reaches the potential's own fluctuation (≥ 100 %) or blows up has left the
  // integrator's stable range: it is marked at the 100 % line, not drawn as a point of its curve (the
  // axis once ran to 10⁸ %).
  const double diverged_percent = study.diverged_percent;
  chart_series gone_h{"diverged (≥ 100 %)", {}, {}, true}, gone_cpu{"diverged (≥ 100 %)", {}, {}, true};
  for (auto* g : {&gone_h, &gone_cpu}) g->colour = "#000000", g->point_type = 2, g->point_size = 1.5;
  for (const auto& sw : study.sweeps) {
    chart_series a{sw.integrator, {}, {}, false}, c{sw.integrator, {}, {}, false};
    for (const auto& p : sw.points) {
      const double h = p.h_fs;
      if (!p.failed) {
        const auto& r = p.result;
        const double per_ps = r.cpu_ms_per_step * 1000 / h;
        table << "| " << sw.integrator << " | " << r.f << " | " << runs::significant_text(h, 3) << " | " << runs::significant_text(h / r.f, 3) << " | " << runs::significant_text(r.ratio_mean, 3) << " | "
              << (r.runs > 1 ? runs::significant_text(r.ratio_error, 2) : std::string()) << " | " << runs::significant_text(r.ms_per_step, 3) << " | " << runs::significant_text(r.cpu_ms_per_step, 3) << " | " << runs::significant_text(per_ps, 3) << " | " << runs::significant_text(r.potential_per_molecule, 5)
              << " | " << runs::significant_text(r.temperature, 4) << " | " << runs::significant_text(r.energy_drift_per_ps, 2) << " |\n";
        points << sw.integrator << "," << r.f << "," << h << "," << h / r.f << "," << r.runs << "," << p.T_ps << ","
               << r.ratio_mean << "," << (r.runs > 1 ? r.ratio_error : std::nan("")) << "," << r.cpu_ms_per_step << ","
               << per_ps << "," << r.potential_per_molecule << "," << r.temperature << "," << r.energy_drift_per_ps << ","
               << (r.ratio_mean < diverged_percent ? 0 : 1) << "\n";
        if (!(r.ratio_mean < diverged_percent)) {
          gone_h.x.push_back(h / r.f), gone_h.y.push_back(diverged_percent);
          gone_cpu.x.push_back(per_ps), gone_cpu.y.push_back(diverged_percent);
          failures << "- " << sw.integrator << " at h = " << runs::significant_text(h, 3) << " fs: ΔE/ΔV = "
                   << runs::significant_text(r.ratio_mean, 3) << " %, beyond the stable range\n";
          continue;
        }
        a.x.push_back(h / r.f), a.y.push_back(r.ratio_mean);
        c.x.push_back(per_ps), c.y.push_back(r.ratio_mean);
      } else {
        table << "| " << sw.integrator << " | | " << runs::significant_text(h, 3) << " | | diverged | | | | | | | |\n";
        failures << "- " << sw.integrator << " at h = " << runs::significant_text(h, 3) << " fs: " << p.failure << "\n";
        const int f = p.f;
        gone_h.x.push_back(h / f), gone_h.y.push_back(diverged_percent);
        points << sw.integrator << "," << f << "," << h << "," << h / f << "," << p.runs << "," << p.T_ps
               << ",,,,,,,,1\n";
      }
    }
    if (sw.integrator == "SIER2")
      slopes << "- SIER2: slope " << runs::significant_text(runs::liquid_water_slope(sw, diverged_percent, 2.01), 3) << " over h/f ≤ 2 fs (order 2 expected)\n";
    if (sw.integrator == "SIER4")
      slopes << "- SIER4: slope " << runs::significant_text(runs::liquid_water_slope(sw, diverged_percent, 1.01), 3) << " over h/f ≤ 1 fs (order 4 expected; "
             << runs::significant_text(runs::liquid_water_slope(sw, diverged_percent, 2.01), 3) << " with h/f = 2 fs, where the error grows faster than h⁴)\n";
    fig1.series.push_back(std::move(a));
    cpu.series.push_back(std::move(c));
  }
  md << "## " << s.title << "\n\n"
     << "van Zon & Schofield section V.C: 512 rigid water molecules at 297 K and 0.9973 g/cm³ (cubic box of "
     << runs::significant_text(study.box_A, 5)
     << " Å, periodic, minimum image). Model: TIP3P (Jorgensen et al. 1983; the paper does not say which of its models; "
        "TIP3P's three massive sites let LAMMPS integrate the very same rigid body). Site–site Coulomb and O–O "
        "Lennard-Jones with a smooth molecular cutoff: the whole molecule-pair energy times a C³ switch of the O–O "
        "distance from 9.5 to 11 Å (width 1.5 Å). Units and constants: LAMMPS `real`. Start: lattice, random "
        "orientations, "
     << runs::significant_text(b.sizes.equilibration_ps, 3) << " ps with a Berendsen thermostat (τ = 0.1 ps), then NVE.\n\n"
     << "SIER2/N2:BAC:2 and SIER4/P1:BAC:5 are SIER2 and SIER4 with the exact free rotation replaced by a dedicated "
        "rotor solved for the TIP3P body (moments "
     << study.moments_text[0] << ", " << study.moments_text[1] << ", " << study.moments_text[2]
     << " g/mol·Å², I₃ = I₁ + I₂ exactly): the solver's best-ranked N and P solutions for it (`rotlie solve --family N` and "
        "`--family P --scheme P1 --perm BAC` with these moments).\n\n"
     << "Budget: " << b.words << ". ΔE/ΔV is the rms fluctuation of the total energy over that of the potential energy, "
     << "sampled every step; the ± is the standard error over the runs (blank with one run). Times were measured "
        "with two threads on a machine shared with other jobs: CPU time (both threads together) is the robust "
        "measure, wall time depends on the load.\n\n";
  for (const auto& [chart_of, gone] : {std::pair{&fig1, &gone_h}, std::pair{&cpu, &gone_cpu}}) {
    chart_of->horizontal_line = diverged_percent;
    chart_of->horizontal_label = "100 %: stable range ends";
    if (!gone->x.empty()) chart_of->series.push_back(*gone);
  }
  write_file_atomically(options.out_dir / "liquid_water_points.csv", points.str());
  s.files.push_back(options.out_dir / "liquid_water_points.csv");
  const auto f1 = write_chart(options.out_dir, "liquid_water_fig1", fig1);
  const auto f2 = write_chart(options.out_dir, "liquid_water_cpu", cpu);
  s.files.insert(s.files.end(), f1.written.begin(), f1.written.end());
  s.files.insert(s.files.end(), f2.written.begin(), f2.written.end());
  md << chart_markdown(f1, "liquid_water_fig1", "vZS Fig. 1 regenerated and extended: ΔE/ΔV against h/f.")
     << chart_markdown(f2, "liquid_water_cpu", "ΔE/ΔV against measured time per simulated ps.") << "\n"
     << table.str() << "\nFitted slopes:\n\n" << slopes.str() << "\n";
  if (!failures.str().empty()) md << "Failures (where each integrator stops working):\n\n" << failures.str() << "\n";
  if (!options.full)
    if (const auto shipped = runs::shipped_file("vzs-fig1/liquid_water_points.csv")) md << shipped_fig1(options, *shipped, s.files);

  // physical sanity: g_OO(r) and V/N
  const auto& g = study.g_OO;
  chart gr;
  gr.title = "O–O radial distribution function, TIP3P, 297 K";
  gr.x_label = "r (Å)";
  gr.y_label = "g_OO(r)";
  gr.log_x = gr.log_y = false;
  chart_series gs{"rotlie (MRDL, h = 1 fs)", {}, {}, false};
  std::pair<double, double> peak{0, 0};
  for (const auto& [r, v] : g) {
    gs.x.push_back(r), gs.y.push_back(v);
    if (r < 3.5 && v > peak.second) peak = {r, v};
  }
  gr.series.push_back(std::move(gs));
  const auto f3 = write_chart(options.out_dir, "liquid_water_gOO", gr);
  s.files.insert(s.files.end(), f3.written.begin(), f3.written.end());
  md << "### Physical sanity\n\n| quantity | rotlie | TIP3P, published |\n|:--|--:|--:|\n"
     << "| potential energy per molecule (kcal/mol) | " << runs::significant_text(study.v_per_molecule, 4) << " (at " << runs::significant_text(study.temperature, 4)
     << " K, 11 Å switched cutoff) | −9.86 (Jorgensen 1983, 298 K, 8.5 Å cutoff) |\n"
     << "| g_OO first peak position (Å) | " << runs::significant_text(peak.first, 3) << " | ≈ 2.75–2.8 |\n"
     << "| g_OO first peak height | " << runs::significant_text(peak.second, 3) << " | ≈ 2.7–2.8 |\n\n"
     << "The published values are quoted as commonly cited for TIP3P; the cutoffs differ, so agreement within a few "
        "per cent is what to expect. g(r) from "
     << runs::significant_text(b.sizes.rdf_ps, 3) << " ps sampled every 10 fs, bins of 0.05 Å.\n\n"
     << chart_markdown(f3, "liquid_water_gOO", "O–O radial distribution function.") << "\n";

  // LAMMPS side by side
  md << "### Side by side with LAMMPS\n\n";
  if (!study.lammps_ran) {
    md << "LAMMPS (`lmp`) is not installed here, or it failed: the comparison is skipped.\n\n";
  } else {
    const double V_mine = study.V_rotlie, V_theirs = study.V_lammps, worst = study.worst_force, scale = study.force_scale;
    md << "Same configuration, same site pair style (`lj/cut/coul/dsf`, α = 0.2 Å⁻¹, 11 Å, LJ shifted, intramolecular pairs "
          "excluded; rotlie implements it for this comparison only, with LAMMPS's polynomial erfc): V = "
       << runs::significant_text(V_mine, 15) << " (rotlie) and " << runs::significant_text(V_theirs, 15) << " kcal/mol (LAMMPS), relative difference "
       << runs::significant_text(std::abs(V_mine - V_theirs) / std::abs(V_theirs), 2) << "; largest site-force difference " << runs::significant_text(worst, 2)
       << " kcal/mol/Å against forces up to " << runs::significant_text(scale, 3) << ".\n\n"
       << "NVE at h = 1 fs with the same map: LAMMPS `fix rigid/nve/small` (NO_SQUISH; its principal axes in decreasing "
          "moment, planar rotations 3, 2, 1, 2, 3) is rotlie's Strang-TV with the table rotor ABCBA2:ABC in increasing-moment "
          "axes, i.e. MRDL; 100 steps agree to 3e-13 Å (test liquid_water_lammps_test).\n\n"
       << "| program | threads/ranks | wall ms/step | CPU ms/step | ΔE/ΔV (%) |\n|:--|--:|--:|--:|--:|\n";
    for (const auto& t : study.rotlie_timings)
      md << "| rotlie | " << t.threads << " | " << runs::significant_text(t.wall_ms, 3) << " | " << runs::significant_text(t.cpu_ms, 3) << " | " << runs::significant_text(t.ratio_percent, 3) << " |\n";
    for (const auto& t : study.lammps_timings) {
      if (!t.ran)
        md << "| LAMMPS | " << t.threads << " | skipped | | |\n";
      else
        md << "| LAMMPS | " << t.threads << " | " << runs::significant_text(t.wall_ms, 3) << " | ≈ " << runs::significant_text(t.cpu_ms, 3) << " | "
           << runs::significant_text(t.ratio_percent, 3) << " |\n";
    }
    md << "\n" << b.sizes.lammps_steps << " steps from the equilibrated start. LAMMPS's CPU time is its wall time times its reported CPU use.\n\n";
  }
  s.markdown = md.str();
  return s;
}

}  // namespace

report_section liquid_water_section(const report_options& options) {
  if (options.quick) return section(options, {{1, 0.1, 3, 0.2, 100}, "quick: one 0.1-ps run per point, 3 ps of equilibration"});
  return section(options, {{1, 0.25, 5, 1, 500}, "one 0.25-ps run per point, 5 ps of equilibration (the paper's nine 1-ps runs: the full section)"});
}

report_section liquid_water_section_full(const report_options& options) {
  return section(options, {{9, 1, 10, 2, 1000}, "nine 1-ps runs per point (the paper's statistics), 10 ps of equilibration"});
}

}  // namespace rotlie::reports
