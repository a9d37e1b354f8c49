// Report section "Audit of the paper's statements" (LV sections 4 and 5): one table, every
// statement next to rotlie's number from this run and a verdict. Claims on the files of earlier
// sections are audit_file_claims.cpp's; the claims below compare the paper with the measurements of
// runs::lv_audit_study (cheap: exact rationals, costs, timings, the R family and a few P systems for
// water, ~3 s of CPU).
#include <algorithm>
#include <limits>
#include <sstream>

#include "rotlie/reports/audit_claim.hpp"
#include "rotlie/reports/audit_table.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "sections.hpp"
#include "rotlie/runs/lv_audit_study.hpp"
#include "rotlie/runs/number_text.hpp"

namespace rotlie::reports {

namespace {

// What the claims below read: the measurements of runs::lv_audit_study, and which sections ran.
struct library_results {
  const report_options& options;
  runs::lv_audit_study_result measured;
  bool ran(const std::string& section) const {
    return options.sections.empty() || std::count(options.sections.begin(), options.sections.end(), section);
  }
};

using library_claim = audit_claim<library_results>;

// The measurements of runs::lv_audit_study, as the claims below compare them (each reads one field).

// LV 4.1, 5.2, 5.3: the rotations per step behind (12/9)^4 and (12/11)^4.
measurement costs(library_results& lib, const library_claim&) {
  const auto& m = lib.measured;
  return measurement::of_names({std::to_string(m.cost_mclachlan), std::to_string(m.cost_n2), std::to_string(m.cost_p1),
                                std::to_string(m.cost_r4)},
                               "RS4 S5 McLachlan " + std::to_string(m.cost_mclachlan) + ", N2 BAC (2) " + std::to_string(m.cost_n2) +
                                   ", P1 BAC (5) " + std::to_string(m.cost_p1) + ", R ABC (4) (9 stages RS) " + std::to_string(m.cost_r4));
}

// LV 4.1's cost model: the largest CPU time per rotation over the smallest.
measurement cost_spread(library_results& lib, const library_claim&) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  std::string v;
  for (const auto& [name, per_rotation] : lib.measured.seconds_per_rotation) {
    lo = std::min(lo, per_rotation), hi = std::max(hi, per_rotation);
    v += (v.empty() ? "" : ", ") + name + " " + runs::fixed_text(per_rotation * 1e9, 1) + " ns";
  }
  return measurement::of(hi / lo, "per rotation: " + v + " (spread " + runs::fixed_text(hi / lo, 2) + "×; thread CPU time, double stepper)");
}

// LV 4.3: whether Fassò's and Hairer-Vilmart's (0.345, 0.653, 1) is refused as a body.
measurement fasso_refused(library_results& lib, const library_claim&) {
  const auto& why = lib.measured.fasso_rejection;
  return measurement::of_flag(!why.empty(), why.empty() ? "accepted as a body" : "rejected: " + why);
}

// LV 4.3: water's I1 and I2 rounded to 3 decimals.
measurement water_moments(library_results& lib, const library_claim&) {
  const double I1 = lib.measured.water_I1, I2 = lib.measured.water_I2;
  return measurement::of_names({runs::fixed_text(I1, 3), runs::fixed_text(I2, 3)},
                               "rotlie's \"water\": (" + runs::fixed_text(I1, 5) + ", " + runs::fixed_text(I2, 5) + ", 1)");
}

// LV 4.2: for the spherical top the R part vanishes for every permutation, the S part does not.
measurement sphere_rs_trivial(library_results& lib, const library_claim&) {
  const bool all_zero = lib.measured.sphere_r_zero, s_nonzero = lib.measured.sphere_s_nonzero;
  return measurement::of_flag(all_zero && s_nonzero, std::string("R part ") + (all_zero ? "= 0" : "≠ 0") + " for every permutation; S part " +
                                                         (s_nonzero ? "≠ 0" : "= 0"));
}

// LV 4.1: the largest relative difference of the R^9 attitude error and √3 × the quadratic mean of
// the angular errors of the three principal axes, for small angles.
measurement small_angle_error(library_results& lib, const library_claim&) {
  const double worst = lib.measured.small_angle_worst;
  return measurement::of(worst, "largest relative difference " + runs::significant_text(worst, 2));
}

// LV 4.1 (from 3.1.2): the permutations where RSRSRSR's remainder equals SRSRSRS's at every order.
measurement sr_equal_at(library_results& lib, const library_claim&) {
  const auto& equal_at = lib.measured.sr_equal_at;
  return measurement::of_names({equal_at}, "equal at permutation(s): " + (equal_at.empty() ? std::string("none") : equal_at) +
                                               " (checked to order 5)");
}

// LV 5.1: the points of rotlie's --grid 200.
measurement body_grid_size(library_results& lib, const library_claim&) {
  const auto all = lib.measured.grid_points, asymmetric = lib.measured.grid_asymmetric;
  return measurement::of(static_cast<double>(all), std::to_string(all) + " points, " + std::to_string(asymmetric) +
                                                       " computed after skipping " + std::to_string(all - asymmetric) + " symmetric tops");
}

// LV 4.3, Fig. 5: the numerically best R for water, over all its solutions.
measurement best_r(library_results& lib, const library_claim&) {
  const auto& ranked = lib.measured.r_measured;
  if (ranked.empty()) return measurement::absent("no R solution measured");
  const std::string second =
      ranked.size() > 1 ? "; next " + ranked[1].second + " at " + runs::fixed_text(ranked[1].first / ranked[0].first, 2) + "×" : "";
  return measurement::of_names({ranked[0].second}, "best of " + std::to_string(ranked.size()) + ": " + ranked[0].second + second +
                                                       "; R ABC (4) is #" + std::to_string(lib.measured.r_abc4_rank) + " by ‖H_R5‖");
}

// LV 4.3, Fig. 5: the numerically best among the P with the smallest analytic remainders (ranked
// from the dedicated section's solutions_water_P.json).
measurement best_p(library_results& lib, const library_claim&) {
  if (!lib.measured.best_p) return measurement::absent(lib.measured.best_p_missing);
  const auto& b = *lib.measured.best_p;
  return measurement::of_names({b.measured[0].second}, "best: " + b.measured[0].second + "; P1 BAC (5) is #" + std::to_string(b.p1_rank) +
                                                           " of " + std::to_string(b.solutions) + " by ‖H_R5‖; the analytic favourite " +
                                                           b.favourite.second + " is " +
                                                           runs::fixed_text(b.favourite.first / b.p1_constant, 2) +
                                                           "× less accurate than P1 BAC (5)");
}

// id, statement (LV), where, tolerance, sections read, the paper's value and comparison, measurement.
const std::vector<library_claim>& computed_claims() {
  static const std::vector<library_claim> claims = {
      {"small-angle-error",
       "For small angles the R^9 attitude error is √3 × the quadratic mean of the angular errors of the three principal axes", "4.1",
       "relative difference below 1e-4 for rotations of 1e-2 and 1e-3 rad about three axes", {}, below(1e-4), small_angle_error, {}},
      {"sr-schemes-redundant",
       "RSRSRSR with the parts of I1 and I3 exchanged has the remainder of SRSRSRS at every order, so SR schemes need not be "
       "considered",
       "4.1 (from 3.1.2)",
       "H_R2 … H_R5 of RSRSRSR equal SRSRSRS's (ABC) exactly at permutation CBA only (water; three rational (a1, b1))", {},
       same_names({"CBA"}), sr_equal_at, {}},
      {"water-moments", "Water: I1 = 10220/29376 ≃ 0.348, I2 = 19187/29376 ≃ 0.653, I3 = 1", "4.3", "rounded to 3 decimals", {},
       same_names({"0.348", "0.653"}), water_moments, {}},
      {"fasso-moments", "The moments (0.345, 0.653, 1) used by Fassò (2003) and Hairer and Vilmart (2006) are not a physical body",
       "4.3", "lie::parse_moments rejects them (I1 + I2 = 0.998 < I3)", {}, property_holds(), fasso_refused, {}},
      {"sphere-rs-trivial", "Spherical top: the RS schemes are trivial, R reduces to the identity", "4.2",
       "the R part of the Hamiltonian is exactly 0 at I = (1, 1, 1) for all six permutations", {}, property_holds(), sphere_rs_trivial, {}},
      {"costs",
       "Costs: RS4 S5 McLachlan 12 C0, an N integrator 9 C0, a P integrator 11 C0 (an RS scheme of N stages costs N + 1)",
       "4.1, 5.2, 5.3", "rotations per step of rotlie's tables equal to these", {}, same_names({"12", "9", "11", "10"}), costs, {}},
      {"cost-model", "Cost model: every rotation costs the same C0, so a step costs its number of rotations (RS: stages + 1)", "4.1",
       "CPU time per rotation (per step / C) of N2 BAC (2), R ABC (4), P1 BAC (5) and RS4 S5 McLachlan within a factor 1.25", {},
       at_most(1.25), cost_spread, {}},
      {"water-best-r", "Water: the numerically best integrator R is R ABC (4)", "4.3, Fig. 5",
       "smallest error/(h/C)^4 among all R solutions for water", {}, same_names({"R ABC (4)"}), best_r, {}},
      {"water-best-p", "Water: among the P integrators of smallest analytic remainder, the numerically best is P1 BAC (5)",
       "4.3, Fig. 5", "smallest error/(h/C)^4 among the 10 P of smallest ‖H_R5‖ (and P1 BAC (5))", {"dedicated"},
       same_names({"P1 BAC (5)"}), best_p, {}},
      {"body-grid", "The triangle ESA is sampled by a grid of 40,401 points, symmetric tops skipped", "5.1",
       "rotlie's --grid 200 has 40,401 points", {}, equal_to(40401), body_grid_size, {}},
  };
  return claims;
}

std::string cell(std::string s) {
  for (auto& c : s)
    if (c == '|') c = '/';
  return s;
}

}  // namespace

report_section audit_section(const report_options& options) {
  if (options.progress) options.progress("Audit: the paper's statements (LV sections 4 and 5)");
  report_section s;
  s.title = "Audit of the paper's statements";
  audit_inputs in;
  in.folder = options.out_dir;
  in.maps_folder = options.maps_dir;
  in.quick = options.quick;
  for (const auto& key : report_section_keys())
    if (options.sections.empty() || std::count(options.sections.begin(), options.sections.end(), key)) in.sections_run.insert(key);
  auto rows = audit_rows_from_reports(in);

  runs::lv_audit_options audit_options;
  audit_options.quick = options.quick;
  if (in.sections_run.count("dedicated")) audit_options.solutions_water_P = options.out_dir / "solutions_water_P.json";
  library_results lib{options, runs::lv_audit_study(audit_options)};
  const auto computed = evaluate_claims(computed_claims(), lib);
  rows.insert(rows.begin(), computed.begin(), computed.end());
  const double cpu = lib.measured.cpu_seconds;

  std::filesystem::create_directories(options.out_dir / "audit");
  write_file_atomically(options.out_dir / "audit" / "audit.csv", audit_csv(rows));
  write_file_atomically(options.out_dir / "audit" / "audit.json", audit_json(rows).dump(2) + "\n");
  s.files = {options.out_dir / "audit" / "audit.csv", options.out_dir / "audit" / "audit.json"};

  int counts[4] = {0, 0, 0, 0};
  for (const auto& r : rows) ++counts[static_cast<int>(r.verdict)];
  std::ostringstream md;
  md << "## " << s.title << " (LV sections 4 and 5)\n\n"
     << "Each statement of Laskar & Vaillant (2018), sections 4 and 5, paraphrased with its number, next to rotlie's own number from "
        "this run: either computed here through the library or read from the files the earlier sections of this run wrote "
        "(accuracy curves, solver solutions, maps, measured map ratios). A row whose section did not run in this run says so and "
        "shows no number. Tolerances are per row; \"about N times\" is read as within 20 %. Files: [audit/audit.csv](audit/audit.csv), "
        "[audit/audit.json](audit/audit.json).\n\n"
     << counts[0] << " statements hold, " << counts[1] << " do not hold, " << counts[2] + counts[3]
     << " are not checked in this run. The audit's own computations took " << runs::fixed_text(cpu, 1) << " s of CPU time.\n\n"
     << "| statement (LV) | where | rotlie (this run) | tolerance | verdict |\n|:--|:--|:--|:--|:--|\n";
  for (const auto& r : rows)
    md << "| " << cell(r.statement) << " | " << cell(r.where) << " | " << cell(r.value) << " | " << cell(r.tolerance) << " | "
       << (r.verdict == audit_verdict::does_not_hold ? "**does not hold**" : cell(verdict_text(r))) << " |\n";
  md << "\n";
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
