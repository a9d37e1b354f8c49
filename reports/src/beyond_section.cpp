// Report section "Beyond the paper": dedicated 6th-order schemes for water (H_R3 = H_R5 = 0, LV's closing
// remark) against the general 6th-order compositions of the literature at their best permutation and the
// 4th-order champions of LV section 4. The search, the polishing and the curves are runs::sixth_order_study;
// this file formats and draws them.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "sections.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/sixth_order_study.hpp"

namespace rotlie::reports {

// From the runs library (rotlie::runs):
using runs::cpu_for_error;
using runs::error_at_cpu;
using runs::ratio_at_equal_cpu_time;
using runs::ratio_at_equal_reduced_step;
using runs::scheme_curve;

namespace {

constexpr int digits = runs::sixth_order_digits;
constexpr int default_starts = runs::sixth_order_default_starts, full_starts = runs::sixth_order_full_starts;

void search_text(section_writer& w, const runs::sixth_order_study_result& study) {
  const auto& h = study.statistics;
  const double seconds = study.search_seconds;
  const auto& skipped = study.skipped;
  auto& md = w.md;
  md << "### The search\n\n"
     << "Conditions: a palindromic word is of order 6 for a body when H_R3 = H_R5 = 0, dim L3 + dim L5 = 2 + 6 = 8 "
        "conditions; 21-stage ABC palindromes have 11 names, less the 3 first-order conditions, so 8 free "
        "coefficients: a square system. There are 511 words × 6 permutations = 3 066 systems. Method: "
        "Levenberg–Marquardt in double from random starts in [−1, 1]^8, then Newton in long double and in CLN "
        "long floats; a root is written with "
     << digits << " digits and every exact condition is evaluated at the written decimals (the residual, relative to "
        "the size of its terms).\n\n"
     << (w.options.full ? "This run (`--full`) scanned every system with " + std::to_string(full_starts) + " starts each. "
                        : "The default run searches only the systems listed below with " +
                              std::to_string(w.options.quick ? default_starts / 4 : default_starts) +
                              " starts each (the best systems of the broad scan, which `--full` or `rotlie sixth --inertia "
                              "water --all` repeats). ")
     << "CPU: " << runs::fixed_text(seconds, 1) << " s.\n\n"
     << "| systems | with real roots | starts | converged | distinct roots | hit once | hit twice | hit ≥ 3 | Good–Turing f1/N | Chao1 |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n"
     << "| " << h.systems << " | " << h.with_roots << " | " << h.starts << " | " << h.converged << " | " << h.roots << " | "
     << h.hit_once << " | " << h.hit_twice << " | " << h.hit_more << " | " << runs::fixed_text(h.unseen, 2) << " | " << runs::fixed_text(h.chao1, 0)
     << " |\n\n"
     << "Good–Turing's f1/N estimates the probability that the next converged start finds a root not yet seen; "
        "Chao1 = S + f1²/(2 f2) estimates how many roots the starting box reaches. "
     << (2 * h.hit_once > h.roots ? "Most roots were hit once: the roots found are a small part of those that exist."
                                  : "Most roots were hit more than once: the search is near saturation in these systems.")
     << "\n\n";
  if (!skipped.empty()) {
    md << "Roots not polished (singular Jacobian: not isolated): ";
    for (std::size_t i = 0; i < skipped.size(); ++i) md << (i ? "; " : "") << "`" << skipped[i] << "`";
    md << ".\n\n";
  }
}

void tables_text(section_writer& w, const std::vector<runs::sixth_order_found>& found) {
  auto& md = w.md;
  md << "### The dedicated 6th-order schemes found (best ‖H_R7‖ first)\n\n"
     << "‖H_R7‖: the Euclidean norm of H_R7's coefficients on Theorem 1's monomials, body scaled to I3 = 1. "
        "Slopes: mean attitude error against h in float128, G0 = (1, 1, 1), T = 1, h = 1/16 … 1/256, fitted over the "
        "five points; on water and on the body (1/2, 4/5, 1), where a dedicated scheme must lose its order.\n\n"
     << "| scheme | cost C | ‖H_R7‖ | ‖H_R7‖·C⁶ | residual | slope, water | slope, other body | hits |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& f : found) {
    const int c = f.cost;
    md << "| " << f.table.name << " | " << c << " | " << runs::scientific_or_dash(f.remainder7, 2) << " | " << runs::scientific_or_dash(f.remainder7 * std::pow(c, 6), 2) << " | "
       << runs::scientific_or_dash(f.residual, 2) << " | " << runs::fixed_text(f.slope_water, 3) << " | " << runs::fixed_text(f.slope_other, 2) << " | " << f.hits << " |\n";
  }
  md << "\n";
  for (const auto& f : found) {
    md << "`" << f.table.name << "` (word " << f.table.word << "), every stage:\n\n```\n";
    for (const auto& s : f.table.stages) md << s.part << " " << s.name << " " << s.value << "\n";
    md << "```\n\n";
  }
}

// Isolated 6th-order solutions for the spherical top: polished roots with a regular Jacobian.
void sphere_text(section_writer& w, const runs::sixth_order_study_result& study) {
  auto& md = w.md;
  md << "### The spherical top\n\n"
     << "Permutation ABC only (the permutations of the sphere are the same body). Each root below polishes to "
     << digits << " digits with quadratic convergence, and its Jacobian (rows scaled by Σ|terms|) has "
        "σmin/σmax far above round-off: regular, isolated solutions. Slopes in float128 as above; on water the "
        "scheme must lose its order.\n\n"
     << "| scheme | ‖H_R7‖ | residual | σmin/σmax | slope, sphere | slope, water |\n|---|---|---|---|---|---|\n";
  for (const auto& r : study.sphere) {
    if (r.polished)
      md << "| D6:" << r.word << ":ABC (sphere) | " << runs::scientific_or_dash(r.remainder7, 2) << " | " << runs::scientific_or_dash(r.residual, 2)
         << " | " << runs::scientific_or_dash(r.condition, 2) << " | " << runs::fixed_text(r.slope_sphere, 3) << " | "
         << runs::fixed_text(r.slope_water, 2) << " |\n";
    else
      md << "| D6:" << r.word << ":ABC | " << runs::scientific_or_dash(r.remainder7, 2) << " | not polished: " << r.failure << " | "
         << runs::scientific_or_dash(r.condition, 2) << " | | |\n";
  }
  md << "\n";
}

}  // namespace

report_section beyond_section(const report_options& options) {
  section_writer w(options, "Beyond the paper: dedicated 6th-order schemes", "Beyond the paper");
  auto& md = w.md;
  md << "LV end with \"it is also possible to construct 6th-order integrators but the system of equations becomes more "
        "difficult to solve\". This section solves it numerically for water and compares the schemes with the general "
        "6th-order compositions (Yoshida 1990; Kahan & Li 1997; Blanes & Moan 2002) and with the 4th-order champions of "
        "LV section 4. Budget: the default about 5–10 s of CPU on one core; `--full` adds the broad scan of all 3 066 systems at "
     << full_starts << " starts (measured: 892 s of CPU on one core).\n\n";

  const auto study = runs::sixth_order_study(options.quick, options.full, [&](const std::string& line) { w.progress(line); });
  for (const auto& f : study.found) {
    write_file_atomically(options.out_dir / f.file, f.text);
    w.section.files.push_back(options.out_dir / f.file);
  }
  search_text(w, study);
  tables_text(w, study.found);
  sphere_text(w, study);
  const auto &dedicated6 = study.dedicated6, &general6 = study.general6, &fourth = study.fourth;

  // The general compositions: float128 slope at their best permutation, ‖H_R7‖.
  md << "### The general 6th-order compositions (best permutation for water)\n\n"
     << "Coefficients from the literature, cited in each table's `source` (`rotlie sixth --references`); ABC versions "
        "of the compositions of ABCBA leapfrogs, and of Blanes & Moan's two-part S10 through the adjoint composition "
        "φ = ABC, φ* = CBA.\n\n"
     << "‖H_R7‖ is shown where the word has at most " << study.remainder_word_limit
     << " stages (the remainder engine's limit; the ABC compositions are longer).\n\n"
     << "| scheme | cost C | K = err/(h/C)⁶ | ‖H_R7‖ | slope (float128) | CPU per rotation (ns) |\n|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < general6.size(); ++k) {
    const auto& c = general6[k];
    const double h7 = study.general[k].remainder7;
    md << "| " << c.name << " | " << c.cost << " | " << runs::scientific_or_dash(c.constant, 2) << " | " << runs::scientific_or_dash(h7, 2) << " | " << runs::fixed_text(study.general[k].quad_slope, 3)
       << " | " << runs::fixed_text(1e9 * c.seconds_per_step / c.cost, 1) << " |\n";
  }
  md << "\n";

  // Charts.
  auto series_of = [](const std::vector<scheme_curve>& curves, bool against_cpu) {
    std::vector<chart_series> out;
    for (const auto& c : curves) {
      chart_series s{c.name, {}, {}};
      for (const auto& p : c.points) {
        s.x.push_back(against_cpu ? p.cpu_seconds : p.h_over_cost);
        s.y.push_back(p.error);
      }
      out.push_back(std::move(s));
    }
    return out;
  };
  auto best_by = [](const std::vector<scheme_curve>& curves, auto key) {
    return *std::min_element(curves.begin(), curves.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  };
  const auto at_cpu = [](const scheme_curve& c) { return c.constant * std::pow(c.seconds_per_step / c.cost, c.order); };
  std::vector<scheme_curve> shown = dedicated6;
  for (const auto& c : general6) shown.push_back(c);
  for (const auto& c : fourth)
    if (c.name == "RS4-S5-McLachlan:CBA" || c.name.rfind("P1:", 0) == 0 || c.name.rfind("N2:", 0) == 0) shown.push_back(c);
  for (const bool against_cpu : {false, true}) {
    chart c;
    c.title = against_cpu ? "Water: error against CPU time" : "Water: error against h/C";
    c.x_label = against_cpu ? "CPU seconds per unit of simulated time (double stepper)" : "h/C (C: rotations per step)";
    c.y_label = "mean attitude error";
    c.series = series_of(shown, against_cpu);
    w.figure(against_cpu ? "beyond-error-cpu" : "beyond-error-h", c,
             against_cpu ? "Mean attitude error against CPU time per unit of simulated time (one core, double stepper)."
                         : "Mean attitude error against the reduced step h/C (long double).");
  }

  // The moonshot questions.
  md << "### The questions\n\n";
  if (dedicated6.empty()) {
    md << "No dedicated scheme was found in this run: no answer.\n\n";
  } else {
    const auto& d6 = best_by(dedicated6, at_cpu);
    const auto& g6 = best_by(general6, at_cpu);
    const double ratio = ratio_at_equal_cpu_time(g6, d6);
    md << "Fitted laws error = K (h/C)^p over the three finest points; CPU per unit time = t_step / h with t_step "
          "the thread's CPU time per step of the double stepper (the fastest of 9 runs of ≥ 10 ms).\n\n"
       << "1. **Is the best dedicated 6th-order scheme ≥ 3× more accurate than the best general 6th-order composition at "
          "equal CPU time?** Best dedicated: `"
       << d6.name << "`; best general (at equal CPU): `" << g6.name << "`. Ratio of errors at equal CPU time: **"
       << runs::scientific_or_dash(ratio, 2) << "** (" << (ratio >= 3 ? "yes" : "no") << "); at equal h/C: " << runs::scientific_or_dash(ratio_at_equal_reduced_step(g6, d6), 2)
       << ". K: " << runs::scientific_or_dash(d6.constant, 2) << " against " << runs::scientific_or_dash(g6.constant, 2) << "; CPU per rotation: "
       << runs::fixed_text(1e9 * d6.seconds_per_step / d6.cost, 1) << " ns against " << runs::fixed_text(1e9 * g6.seconds_per_step / g6.cost, 1)
       << " ns.\n";
    const double e_target = 1e-10, cpu_d = cpu_for_error(d6, e_target);
    bool every = true;
    std::ostringstream rows;
    rows << "| 4th-order scheme | error at the CPU where " << d6.name << " reaches 1e-10 | ratio | crossing error |\n|---|---|---|---|\n";
    for (const auto& c : fourth) {
      const double e4 = error_at_cpu(c, cpu_d);
      // Where the two laws meet: below it the 6th-order scheme needs less CPU for the same error.
      const double crossing = std::pow(cpu_for_error(c, 1) / cpu_for_error(d6, 1), 1.0 / (1.0 / 4 - 1.0 / 6));
      every = every && e4 > e_target;
      rows << "| " << c.name << " | " << runs::scientific_or_dash(e4, 2) << " | " << runs::scientific_or_dash(e4 / e_target, 2) << " | " << runs::scientific_or_dash(crossing, 2) << " |\n";
    }
    md << "2. **Is it more accurate than every 4th-order scheme of rotlie below a mean attitude error of 1e-10 at equal CPU "
          "time?** "
       << (every ? "Yes" : "No") << ": at the CPU time where `" << d6.name << "` reaches 1e-10 ("
       << runs::scientific_or_dash(cpu_d, 2) << " s per unit time), the 4th-order schemes (the reference compositions at their best permutation "
                        "and LV's champions N2 BAC (2), P1 BAC (5), R ABC (4)) reach:\n\n"
       << rows.str() << "\nBelow the crossing error the 6th-order scheme is the cheaper one (its curve is steeper).\n\n";
  }
  // The curves as a CSV (every scheme, every step).
  std::ostringstream csv;
  csv << "scheme,order,cost,h,h_over_cost,error,cpu_seconds_per_unit_time\n";
  for (const auto* group : {&dedicated6, &general6, &fourth})
    for (const auto& c : *group)
      for (const auto& p : c.points)
        csv << c.name << "," << c.order << "," << c.cost << "," << p.h << "," << p.h_over_cost << "," << p.error << ","
            << p.cpu_seconds << "\n";
  write_file_atomically(options.out_dir / "beyond-curves.csv", csv.str());
  w.section.files.push_back(options.out_dir / "beyond-curves.csv");
  md << "All curves: [beyond-curves.csv](beyond-curves.csv). Section CPU: " << runs::fixed_text(study.seconds, 1) << " s.\n\n";
  return w.finish();
}

}  // namespace rotlie::reports
