// The audit's claims checked on the files of this report run: one row per statement of LV (2018),
// sections 4 and 5. The paper's numbers are quoted in the rows (and in lv_paper_tables.hpp);
// every rotlie value is read from a file the same run wrote.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

#include "rotlie/reports/audit_files.hpp"
#include "rotlie/reports/lv_paper_tables.hpp"
#include "rotlie/runs/number_text.hpp"

namespace rotlie::reports {
namespace {

using claim = audit_claim<report_files>;
using outcome = claim_outcome;

constexpr double ratio_tolerance = 0.20;  // the accuracy section's criterion for the paper's "about N times"
constexpr double slope_tolerance = 0.1;

bool is_leapfrog(const std::string& name) { return name.rfind("ABCBA2", 0) == 0 || name.rfind("RSR2", 0) == 0; }

// A paper's table against ours, row by row: how many rows are within tolerance, and the largest
// deviation (the last row of that size).
struct deviations {
  int within = 0;
  double worst = 0;
  std::string worst_name;
  void add(const std::string& name, double deviation, double tolerance) {
    within += std::abs(deviation) <= tolerance;
    if (std::abs(deviation) >= std::abs(worst)) worst = deviation, worst_name = name;
  }
};

constexpr double two_decimals = 0.005 + 1e-9;  // equal to a value printed with two decimals

// ---------------------------------------------------------------- dedicated section (solutions)

// The number of real solutions in a solutions file, against the paper's count.
claim count_claim(std::string id, std::string statement, std::string where, std::string file, std::size_t paper,
                  bool skipped_when_quick) {
  return {std::move(id), std::move(statement), std::move(where), "the same count, exactly", {"dedicated"},
          [=](report_files& f) {
            if (skipped_when_quick && f.quick())
              return outcome::missing("not computed in this run (section dedicated skips R and P with --quick)");
            const auto* j = f.json(file);
            if (!j) return outcome::missing(file + " missing");
            const auto n = j->at("solutions").size();
            return outcome::measured(n == paper, std::to_string(n) + " real solutions");
          }};
}

outcome table3_analytic(report_files& f) {
  const auto* j = f.json("solutions_sphere.json");
  const auto* n5 = j ? find_solution_named(*j, "N5 ABC (2)") : nullptr;
  if (!n5) return outcome::missing("N5 ABC (2) missing");
  deviations d;
  for (const auto& paper : lv_table3)
    if (const auto* s = find_solution_named(*j, paper.integrator))
      d.add(paper.integrator, s->at("analytic_remainder").get<double>() / n5->at("analytic_remainder").get<double>() - paper.analytic,
            two_decimals);
  return outcome::measured(d.within == static_cast<int>(lv_table3.size()),
                           std::to_string(d.within) + " of " + std::to_string(lv_table3.size()) + " equal; largest difference " +
                               runs::significant_text(d.worst, 2) + " (" + d.worst_name + ")");
}

// Every water solution by ‖H_R5‖, smallest first.
std::vector<std::pair<double, std::string>> water_by_remainder(const nlohmann::json& water) {
  std::vector<std::pair<double, std::string>> all;
  for (const auto& s : water.at("solutions")) all.emplace_back(s.at("analytic_remainder").get<double>(), solution_name(s));
  std::sort(all.begin(), all.end());
  return all;
}

outcome table4_members(report_files& f) {
  const auto* water = f.json("solutions_water.json");
  if (!water) return outcome::missing(section_not_run("dedicated"));
  const auto all = water_by_remainder(*water);
  std::string extra, missing;
  std::set<std::string> ours;
  for (std::size_t k = 0; k < std::min<std::size_t>(15, all.size()); ++k) ours.insert(all[k].second);
  for (const auto& paper : lv_table4) {
    const std::string name = paper.integrator;
    if (!ours.count(name)) missing += (missing.empty() ? "" : ", ") + name;
    ours.erase(name);
  }
  for (const auto& n : ours) extra += (extra.empty() ? "" : ", ") + n;
  return outcome::measured(missing.empty() && extra.empty(),
                           missing.empty() && extra.empty() ? "the same 15"
                                                            : "not in rotlie's 15: " + (missing.empty() ? "none" : missing) +
                                                                  "; in rotlie's 15 only: " + (extra.empty() ? "none" : extra));
}

outcome table4_values(report_files& f) {
  const auto* water = f.json("solutions_water.json");
  if (!water) return outcome::missing(section_not_run("dedicated"));
  deviations d;
  for (const auto& paper : lv_table4)
    if (const auto* s = find_solution_named(*water, paper.integrator))
      d.add(paper.integrator, 100 * s->at("analytic_remainder").get<double>() - paper.analytic_e2, two_decimals);
  return outcome::measured(d.within == static_cast<int>(lv_table4.size()),
                           std::to_string(d.within) + " of 15 equal; largest difference " + runs::significant_text(d.worst, 2) + "e-2 (" +
                               d.worst_name + ")");
}

outcome water_smallest_remainders(report_files& f) {
  const auto* water = f.json("solutions_water.json");
  if (!water) return outcome::missing(section_not_run("dedicated"));
  const auto all = water_by_remainder(*water);
  const bool ok = all.size() >= 2 && all[0].second == "N2 BAC (2)" && all[1].second == "N2 ACB (1)";
  return outcome::measured(ok, all[0].second + " (" + runs::significant_text(100 * all[0].first, 3) + "e-2), " + all[1].second + " (" +
                                   runs::significant_text(100 * all[1].first, 3) + "e-2)");
}

// The coefficients of eqs. (74) and (76), quoted with 41 digits, against the solver's certified ones.
claim printed_coefficients_claim(std::string id, const std::string& integrator, std::string where) {
  return {std::move(id), "The coefficients of " + integrator + " printed with 41 digits", std::move(where),
          "each agrees with rotlie's 40-digit certified value to ≥ 38 significant digits", {"dedicated"},
          [integrator](report_files& f) {
            const bool p = integrator[0] == 'P';
            const std::string file = p ? "solutions_water_P.json" : "solutions_water.json";
            if (p && f.quick()) return outcome::missing("not computed in this run (section dedicated skips P with --quick)");
            const auto* j = f.json(file);
            const auto* s = j ? find_solution_named(*j, integrator) : nullptr;
            if (!s) return outcome::missing(integrator + " missing in " + file);
            std::string lacking;
            for (const auto& e : lv_printed_coefficients)
              if (e.integrator == integrator && !(s->contains("coefficients") && s->at("coefficients").contains(e.coefficient)))
                lacking = e.coefficient;
            if (!lacking.empty()) return outcome::missing(integrator + " has no " + lacking + " in " + file);
            double least = 45;
            std::string v;
            for (const auto& e : lv_printed_coefficients)
              if (e.integrator == integrator) {
                const double d = agreeing_digits(s->at("coefficients").at(e.coefficient).get<std::string>(), e.paper);
                least = std::min(least, d);
                v += (v.empty() ? "" : ", ") + std::string(e.coefficient) + ": " + runs::fixed_text(d, 1);
              }
            return outcome::measured(least >= 38, "agreeing digits " + v);
          }};
}

outcome n2_coefficients_positive(report_files& f) {
  const auto* water = f.json("solutions_water.json");
  const auto* s = water ? find_solution_named(*water, "N2 BAC (2)") : nullptr;
  if (!s) return outcome::missing(section_not_run("dedicated"));
  bool positive = true;
  std::string v;
  for (const auto& [k, text] : s->at("coefficients").items()) {
    const bool p = positive_decimal(text.get<std::string>());
    positive = positive && p;
    v += (v.empty() ? "" : ", ") + k + (p ? " > 0" : " ≤ 0");
  }
  return outcome::measured(positive, v);
}

// Spearman ρ of Table 4's analytic remainders against the numeric constants of Fig. 3.
outcome table4_analytic_against_numeric(report_files& f) {
  const auto* water = f.json("solutions_water.json");
  if (!water) return outcome::missing(section_not_run("dedicated"));
  const auto* d = f.ran("accuracy") ? f.chart("fig3_water") : nullptr;
  if (!d) return outcome::missing(section_not_run("accuracy"));
  std::vector<double> analytic, numeric;
  std::string analytic_best, numeric_best;
  double a_min = 1e300, n_min = 1e300;
  for (const auto& paper : lv_table4) {
    const std::string name = paper.integrator;
    const auto* s = find_solution_named(*water, name);
    const auto* c = series(*d, name);
    if (!s || !c) continue;
    analytic.push_back(s->at("analytic_remainder").get<double>());
    numeric.push_back(fit(*c, 4).constant);
    if (analytic.back() < a_min) a_min = analytic.back(), analytic_best = name;
    if (numeric.back() < n_min) n_min = numeric.back(), numeric_best = name;
  }
  return outcome::measured(analytic_best != numeric_best,
                           "analytic favourite " + analytic_best + ", numeric best " + numeric_best +
                               "; Spearman ρ (analytic, numeric) = " + runs::fixed_text(rank_correlation(analytic, numeric), 3) +
                               " over " + std::to_string(analytic.size()));
}

// ---------------------------------------------------------------- accuracy section (LV 4.2-4.3)

// "X about N times more accurate than Y": the ratio of the error constants of two curves of a chart.
claim ratio_claim(std::string id, std::string statement, std::string where, std::string file, std::string worse,
                  std::string better, double paper) {
  return {std::move(id), std::move(statement), std::move(where),
          "our ratio of error/(h/C)^4 (three finest h) within " + percent(ratio_tolerance) + " of " + runs::significant_text(paper, 3) + "×",
          {"accuracy"},
          [=](report_files& f) {
            const auto* d = f.chart(file);
            const auto* w = d ? series(*d, worse) : nullptr;
            const auto* b = d ? series(*d, better) : nullptr;
            if (!w || !b) return outcome::missing("curve missing in " + file + ".csv");
            const double ours = fit(*w, 4).constant / fit(*b, 4).constant;
            return outcome::measured(std::abs(ours / paper - 1) <= ratio_tolerance,
                                     runs::significant_text(ours, 3) + "× (" + series_name(*d, better) + " vs " + series_name(*d, worse) +
                                         ", " + runs::fixed_text(100 * (ours / paper - 1), 1) + " % from the paper)");
          }};
}

// One N curve of a chart among all its N curves: their fits, smallest first, and its own constant.
struct n_standing {
  std::vector<std::pair<std::string, curve_fit>> fits;
  double mine = 0;
  /// Within 5 % of the smallest constant: "the best N" in the paper's sense.
  bool best() const { return mine <= 1.05 * fits.front().second.constant; }
  double to_smallest() const { return mine / fits.front().second.constant; }
};

std::optional<n_standing> standing_of(report_files& f, const std::string& file, const std::string& name) {
  const auto* d = f.chart(file);
  const auto* c = d ? series(*d, name) : nullptr;
  if (!c) return std::nullopt;
  return n_standing{n_fits(*d), fit(*c, 4).constant};
}

outcome sphere_best_n(report_files& f) {
  const auto s = standing_of(f, "fig1_sphere", "N5 ABC (2)");
  if (!s) return outcome::missing("N5 ABC (2) missing in fig1_sphere.csv");
  std::string runner_up;
  for (const auto& [n, c] : s->fits)
    if (n != "N5 ABC (2)" && runner_up.empty()) runner_up = n + " at " + runs::fixed_text(c.constant / s->mine, 3) + "× N5 (2)'s";
  return outcome::measured(s->best(), "smallest: " + s->fits.front().first + "; N5 (2) at " + runs::fixed_text(s->to_smallest(), 3) +
                                          "× the smallest; next " + runner_up + f.quick_note());
}

outcome table3_numeric(report_files& f) {
  const auto* d = f.chart("fig1_sphere");
  const auto* n5 = d ? series(*d, "N5 ABC (2)") : nullptr;
  if (!n5) return outcome::missing("N5 ABC (2) missing in fig1_sphere.csv");
  int found = 0;
  deviations dev;
  for (const auto& paper : lv_table3)
    if (const auto* c = series(*d, paper.integrator)) {
      ++found;
      dev.add(paper.integrator, fit(*c, 4).constant / fit(*n5, 4).constant / paper.numeric - 1, ratio_tolerance);
    }
  return outcome::measured(dev.within == static_cast<int>(lv_table3.size()),
                           std::to_string(dev.within) + " of " + std::to_string(lv_table3.size()) + " within tolerance (" +
                               std::to_string(found) + " found); largest deviation " + runs::fixed_text(100 * dev.worst, 1) + " % (" +
                               dev.worst_name + ")" + f.quick_note());
}

outcome sphere_remainders_correlated(report_files& f) {
  const auto* d = f.chart("fig2_sphere_remainders");
  const auto* ours = d ? series(*d, "rotlie") : nullptr;
  if (!ours) return outcome::missing("series rotlie missing in fig2_sphere_remainders.csv");
  const double rho = rank_correlation(ours->x, ours->y);
  return outcome::measured(rho >= 0.9, "Spearman ρ = " + runs::fixed_text(rho, 3) + " over " + std::to_string(ours->x.size()) + " solutions");
}

outcome water_two_best_n(report_files& f) {
  const auto* d = f.chart("fig3_water");
  if (!d) return outcome::missing(section_not_run("accuracy"));
  const auto fits = n_fits(*d);
  const bool ok = fits.size() >= 2 && ((fits[0].first == "N2 BAC (2)" && fits[1].first == "N2 ACB (1)") ||
                                       (fits[0].first == "N2 ACB (1)" && fits[1].first == "N2 BAC (2)"));
  std::string v = "ranked by error/(h/C)^4: ";
  for (std::size_t k = 0; k < std::min<std::size_t>(3, fits.size()); ++k)
    v += (k ? ", " : "") + fits[k].first + " (" + runs::significant_text(fits[k].second.constant, 3) + ")";
  return outcome::measured(ok, v + f.quick_note());
}

outcome water_best_n_by_step(report_files& f) {
  const auto* d = f.chart("fig3_water");
  if (!d) return outcome::missing(section_not_run("accuracy"));
  std::vector<std::string> n;
  for (const auto& name : d->names)
    if (name[0] == 'N') n.push_back(name);
  const std::size_t levels = d->series.at(n.front()).x.size();
  std::string v;
  bool ok = true;
  for (std::size_t i = 0; i < levels; ++i) {
    std::string best;
    double e = std::numeric_limits<double>::infinity();
    for (const auto& name : n) {
      const auto& c = d->series.at(name);
      if (i < c.y.size() && c.y[i] < e) e = c.y[i], best = name;
    }
    ok = ok && best == (i + 1 == levels ? "N2 BAC (2)" : "N2 ACB (1)");
    v += (i ? "; " : "") + std::string("h=2^-") + std::to_string(i + 1) + ": " + best;
  }
  return outcome::measured(ok, v);
}

outcome water_best_n(report_files& f) {
  const auto s = standing_of(f, "fig3_water", "N2 BAC (2)");
  if (!s) return outcome::missing("N2 BAC (2) missing in fig3_water.csv");
  return outcome::measured(s->best(), "smallest: " + s->fits.front().first + "; N2 BAC (2) at " + runs::fixed_text(s->to_smallest(), 2) +
                                          "× its error at equal h/C" + f.quick_note());
}

outcome water_best_reference(report_files& f) {
  const auto* d = f.chart("fig4_water_reference");
  if (!d) return outcome::missing(section_not_run("accuracy"));
  std::vector<std::pair<double, std::string>> refs;
  for (const auto& n : d->names)
    if (n.find(':') != std::string::npos) refs.emplace_back(fit(d->series.at(n), 4).constant, n);
  std::sort(refs.begin(), refs.end());
  return outcome::measured(!refs.empty() && refs[0].second == "RS4-S5-McLachlan:CBA",
                           "best: " + refs[0].second +
                               (refs.size() > 1 ? "; next " + refs[1].second + " at " + runs::fixed_text(refs[1].first / refs[0].first, 2) + "×"
                                                : std::string()));
}

// Computing time at equal accuracy: error = K (h/C)^4, so the time ratio is (K_P / K_M)^(1/4).
outcome p1_time_saving(report_files& f) {
  const auto* d = f.chart("fig5_water_dedicated");
  const auto* p = d ? series(*d, "P1 BAC (5)") : nullptr;
  const auto* m = d ? series(*d, "RS4-S5-McLachlan") : nullptr;
  if (!p || !m) return outcome::missing(section_not_run("accuracy"));
  const double saved = 1 - std::pow(fit(*p, 4).constant / fit(*m, 4).constant, 0.25);
  return outcome::measured(std::abs(saved - 0.12) <= 0.05, percent(saved) + " at equal h/C");
}

outcome dedicated_time_savings(report_files& f) {
  const auto* d = f.chart("fig5_water_dedicated");
  const auto* m = d ? series(*d, "RS4-S5-McLachlan") : nullptr;
  if (!m) return outcome::missing(section_not_run("accuracy"));
  double best = -1e9;
  std::string v;
  for (const auto* name : {"N2 BAC (2)", "R ABC (4)", "P1 BAC (5)"}) {
    const auto* c = series(*d, name);
    if (!c) continue;
    const double saved = 1 - std::pow(fit(*c, 4).constant / fit(*m, 4).constant, 0.25);
    best = std::max(best, saved);
    v += (v.empty() ? "" : "; ") + std::string(name) + ": " + percent(saved);
  }
  return outcome::measured(best < 0.25, v + " (negative: slower)");
}

// Slopes: all the integrators of Figs. 1, 3-5 are of order 4, the leapfrogs of order 2.
outcome fitted_slopes(report_files& f) {
  int total = 0, within = 0;
  double worst = 0;
  std::string worst_name;
  for (const auto* file : {"fig1_sphere", "fig3_water", "fig4_water_reference", "fig5_water_dedicated"}) {
    const auto* d = f.chart(file);
    if (!d) continue;
    for (const auto& n : d->names) {
      const double order = is_leapfrog(n) ? 2 : 4, dev = fit(d->series.at(n), 4).slope - order;
      ++total;
      within += std::abs(dev) <= slope_tolerance;
      if (std::abs(dev) > std::abs(worst)) worst = dev, worst_name = n + " (" + file + ")";
    }
  }
  return outcome::measured(total > 0 && within == total, std::to_string(within) + " of " + std::to_string(total) +
                                                             " curves within tolerance; largest deviation " + runs::fixed_text(worst, 2) +
                                                             " at " + worst_name + f.quick_note());
}

// ---------------------------------------------------------------- maps (LV 5.2-5.3)

// Distance to the symmetric tops, as the maps section measures it: min(I2 − I1, 1 − I2) ≤ 1/3.
double asymmetry(const audit_map_body& b) { return std::min(b.I2 - b.I1, 1 - b.I2); }

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// The bodies with a ratio in three bands of δ: near the tops (< 1/9), in between, very asymmetric (≥ 2/9).
struct bands {
  int n[3] = {0, 0, 0}, wins[3] = {0, 0, 0};
  std::vector<double> log_ratio[3];
  int total = 0, total_wins = 0;
};

bands band_counts(const audit_map& m) {
  bands b;
  for (const auto& x : m.bodies) {
    if (!x.ratio || *x.ratio <= 0) continue;
    const double d = asymmetry(x);
    const int k = d < 1.0 / 9 ? 0 : d < 2.0 / 9 ? 1 : 2;
    ++b.n[k], ++b.total;
    b.log_ratio[k].push_back(std::log10(*x.ratio));
    if (*x.ratio > 1) ++b.wins[k], ++b.total_wins;
  }
  return b;
}

std::string share(int a, int n) {
  return (n ? runs::fixed_text(100.0 * a / n, 1) : std::string("0")) + " % (" + std::to_string(a) + "/" + std::to_string(n) + ")";
}

std::string grid(const audit_map& m) {
  return " (--grid " + std::to_string(m.K) + ", " + std::to_string(m.bodies.size()) + " bodies)";
}

// A claim on map-FAMILY.jsonl.
claim map_claim(std::string id, std::string statement, std::string where, std::string tolerance, std::string family,
                std::function<outcome(const audit_map&)> measure) {
  return {std::move(id), std::move(statement), std::move(where), std::move(tolerance), {"maps"},
          [family, measure = std::move(measure)](report_files& f) {
            const auto* m = f.map(family);
            return m ? measure(*m) : outcome::missing("map-" + family + ".jsonl missing");
          }};
}

outcome n_wins_somewhere(const audit_map& m) {
  const auto b = band_counts(m);
  const double fraction = b.total ? static_cast<double>(b.total_wins) / b.total : 0;
  std::string where;
  int listed = 0;
  for (const auto& x : m.bodies)
    if (x.ratio && *x.ratio > 1 && listed++ < 5)
      where += (where.empty() ? "" : ", ") + std::string("(") + runs::significant_text(x.I1, 3) + ", " + runs::significant_text(x.I2, 3) + "; δ " +
               runs::significant_text(asymmetry(x), 2) + "; " + x.best + ")";
  return outcome::measured(b.total_wins > 0 && fraction < 0.5,
                           "N better at " + share(b.total_wins, b.total) + (where.empty() ? "" : ": (I1, I2) = " + where) + grid(m));
}

outcome reference_best_near_tops(const audit_map& m) {
  const auto b = band_counts(m);
  const double near = median(b.log_ratio[0]), far = median(b.log_ratio[2]);
  const bool ok = b.n[0] > 0 && b.n[2] > 0 && near < far;
  return outcome::measured(ok, "median log10 ratio " + runs::fixed_text(near, 2) + " near the tops, " + runs::fixed_text(median(b.log_ratio[1]), 2) +
                                   " in between, " + runs::fixed_text(far, 2) + " very asymmetric; N wins " + share(b.wins[0], b.n[0]) +
                                   " near, " + share(b.wins[2], b.n[2]) + " far" + grid(m));
}

outcome p_wins_far_from_tops(const audit_map& m) {
  const auto b = band_counts(m);
  return outcome::measured(b.total_wins > 0 && b.wins[0] == 0,
                           "P wins " + share(b.wins[0], b.n[0]) + " near the tops, " + share(b.wins[1], b.n[1]) + " in between, " +
                               share(b.wins[2], b.n[2]) + " very asymmetric; median log10 ratio " + runs::fixed_text(median(b.log_ratio[0]), 2) +
                               ", " + runs::fixed_text(median(b.log_ratio[1]), 2) + ", " + runs::fixed_text(median(b.log_ratio[2]), 2) + grid(m));
}

outcome singular_points_isolated(const audit_map& m) {
  std::set<std::pair<int, int>> singular;
  std::string v;
  for (const auto& x : m.bodies)
    if (x.singular) {
      singular.insert({x.i, x.j});
      v += (v.empty() ? "" : ", ") + std::string("(") + runs::significant_text(x.I1, 3) + ", " + runs::significant_text(x.I2, 3) + ")";
    }
  bool isolated = true;
  for (const auto& [i, j] : singular)
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        if ((di || dj) && singular.count({i + di, j + dj})) isolated = false;
  return outcome::measured(!singular.empty() && isolated, std::to_string(singular.size()) + " singular bod" +
                                                              (singular.size() == 1 ? "y" : "ies") +
                                                              (v.empty() ? "" : " at (I1, I2) = " + v) + grid(m));
}

// ---------------------------------------------------------------- measured map ratios

const std::string truth_file = "maps-truth/measured-ratios.csv";

// The analytic and measured (equal h/C) ratios of one family's measured bodies, and how many of
// them the two put on different sides of 1.
struct measured_ratios {
  std::vector<double> analytic, measured;
  int flipped = 0;
};

measured_ratios read_measured_ratios(const csv_table& t, const std::string& family) {
  const auto fam = t.column("family"), a = t.column("analytic_ratio"), m = t.column("measured_ratio_h");
  if (!fam || !a || !m) throw std::runtime_error(truth_file + " lacks family, analytic_ratio or measured_ratio_h");
  measured_ratios r;
  for (const auto& rw : t.rows) {
    if (rw[*fam] != family) continue;
    double ar = 0, mr = 0;
    try {
      ar = std::stod(rw[*a]), mr = std::stod(rw[*m]);
    } catch (const std::exception&) {
      continue;
    }
    if (!std::isfinite(ar) || !std::isfinite(mr)) continue;
    r.analytic.push_back(ar), r.measured.push_back(mr);
    r.flipped += (ar > 1) != (mr > 1);
  }
  return r;
}

// A claim on the measured ratios of one family (at least three bodies).
claim truth_claim(std::string id, std::string statement, std::string where, std::string tolerance, std::string family,
                  std::function<outcome(const measured_ratios&)> measure) {
  return {std::move(id), std::move(statement), std::move(where), std::move(tolerance), {"maps-truth"},
          [family, measure = std::move(measure)](report_files& f) {
            const auto* t = f.csv(truth_file);
            if (!t) return outcome::missing(truth_file + " missing");
            const auto r = read_measured_ratios(*t, family);
            if (r.analytic.size() < 3) return outcome::missing("fewer than 3 measured " + family + " bodies in " + truth_file);
            return measure(r);
          }};
}

outcome ratios_correlated(const measured_ratios& r) {
  const double rho = rank_correlation(r.analytic, r.measured);
  return outcome::measured(rho >= 0.8, "Spearman ρ = " + runs::fixed_text(rho, 3) + " over " + std::to_string(r.analytic.size()) + " bodies");
}

outcome verdicts_kept(const measured_ratios& r) {
  const auto n = r.analytic.size();
  return outcome::measured(r.flipped <= 0.1 * static_cast<double>(n), "flips at " + share(r.flipped, static_cast<int>(n)));
}

void add_truth_claims(std::vector<claim>& claims, const std::string& family) {
  claims.push_back(truth_claim("truth-correlation-" + family,
                               "The analytic remainder predicts the measured gain of the best " + family +
                                   " over RS4 S5 McLachlan (section 5 relies on it)",
                               "5 (from 4.2)", "Spearman rank correlation of analytic and measured (equal h/C) ratios ≥ 0.8", family,
                               ratios_correlated));
  claims.push_back(truth_claim("truth-verdicts-" + family,
                               "The analytic verdict \"" + family + " better than RS4 S5 McLachlan\" is the measured one",
                               "5.2-5.3, Figs. 8, 10", "the verdict (ratio > 1) flips at ≤ 10 % of the measured bodies", family,
                               verdicts_kept));
}

}  // namespace

std::vector<audit_claim<report_files>> file_claims() {
  // id, statement (LV), where, tolerance, sections read, measurement.
  std::vector<claim> c = {
      // Dedicated section: the solver's solutions.
      count_claim("sphere-n-count", "Spherical top: the N integrators have 12 real solutions", "4.2, Table 2", "solutions_sphere.json",
                  12, false),
      {"table3-analytic", "Table 3, analytic column: ‖H_R5‖ normalised by N5 (2) (1 to 991.42)", "4.2, Table 3",
       "every ratio equal to the paper's to its two printed decimals (±0.005)", {"dedicated"}, table3_analytic},
      count_claim("water-n-count", "Water: the N integrators have 90 real solutions over the six permutations", "4.3",
                  "solutions_water.json", 90, false),
      {"table4-members", "Table 4 lists the 15 N integrators of smallest analytic remainder for water", "4.3, Table 4",
       "rotlie's 15 smallest ‖H_R5‖ are the same 15 integrators", {"dedicated"}, table4_members},
      {"table4-values", "Table 4: analytic remainders from 1.06e-2 (N2 BAC (2)) to 3.83e-2 (N1 ABC (2))", "4.3, Table 4",
       "every value equal to the paper's to its printed digits (±0.005e-2)", {"dedicated"}, table4_values},
      {"water-smallest-remainders", "Water: the smallest analytic remainders are N2 BAC (2), then N2 ACB (1)", "4.3, Table 4",
       "rotlie's first two by ‖H_R5‖", {"dedicated"}, water_smallest_remainders},
      printed_coefficients_claim("eq74-digits", "N2 BAC (2)", "4.3, eq. (74)"),
      printed_coefficients_claim("eq76-digits", "P1 BAC (5)", "4.3, eq. (76)"),
      {"n2-positive", "Water: all the coefficients of N2 BAC (2) are positive", "4.3, after eq. (74)",
       "every stage coefficient > 0 (the second half cites Sheng 1989, Suzuki 1991: not checked)", {"dedicated"},
       n2_coefficients_positive},
      {"sheng-suzuki", "All-positive coefficients are impossible for a classical 4th-order splitting (Sheng 1989; Suzuki 1991)",
       "4.3, after eq. (74)", "—", {},
       [](report_files&) { return outcome::unverifiable("a theorem the paper cites, not a number of rotlie's"); }},
      {"table4-numeric-choice", "Table 4's analytic remainders are very close, so the best N for water has to be chosen numerically",
       "4.3, Table 4, Fig. 3",
       "the analytic order of Table 4's 15 N differs from the numeric order at the top (the favourites differ)", {"dedicated"},
       table4_analytic_against_numeric},
      count_claim("water-r-count", "Water: the integrator R has 46 real solutions over the six permutations", "4.3",
                  "solutions_water_R.json", 46, true),
      count_claim("water-p-count", "Water: the fifteen integrators P have 724 real solutions in total", "4.3", "solutions_water_P.json",
                  724, true),

      // Accuracy section: the curves of Figs. 1-5.
      {"sphere-best-n", "Spherical top: the best N integrator is N5 (2)", "4.2, Fig. 1, Table 3",
       "N5 (2)'s error constant within 5 % of the smallest among the 12 N solutions", {"accuracy"}, sphere_best_n},
      ratio_claim("sphere-n5-vs-yoshida", "Spherical top: N5 (2) about 700 times more accurate than ABCBA4 SS3 Yoshida at equal h/C",
                  "4.2, Fig. 1", "fig1_sphere", "ABCBA4-SS3-Yoshida", "N5 ABC (2)", 700),
      {"table3-numeric", "Table 3, numeric column: the 11 numeric remainders normalised by N5 (2) (1.00 to 1120.50)", "4.2, Table 3",
       "every ratio within " + percent(ratio_tolerance) + " of the paper's", {"accuracy"}, table3_numeric},
      {"sphere-remainders-correlated",
       "The analytic remainder is very well correlated with the numeric one (spherical top, 11 N solutions)", "4.2, Fig. 2",
       "Spearman rank correlation ≥ 0.9 between rotlie's analytic and numeric ratios", {"accuracy"}, sphere_remainders_correlated},
      {"water-two-best-n",
       "Water: the numerically best N integrators are N2 BAC (2) and N2 ACB (1) (the two smallest analytic remainders of Table 4)",
       "4.3, Fig. 3", "the two smallest error constants among Table 4's 15 N are these two", {"accuracy"}, water_two_best_n},
      {"water-best-n-by-step", "Water: at the smallest step N2 BAC (2) is the best N, at the other steps N2 ACB (1)", "4.3, Fig. 3",
       "the N with the smallest error at each h = 2^-i of the run", {"accuracy"}, water_best_n_by_step},
      {"water-best-n", "Water: the best N integrator is N2 BAC (2) (the paper's choice, eq. 73)", "4.3, Fig. 3",
       "N2 BAC (2)'s error constant within 5 % of the smallest among Table 4's 15 N", {"accuracy"}, water_best_n},
      ratio_claim("water-n2-vs-yoshida", "Water: N2 BAC (2) about 170 times more accurate than ABCBA4 SS3 Yoshida (best permutation)",
                  "4.3, Fig. 3", "fig3_water", "ABCBA4-SS3-Yoshida", "N2 BAC (2)", 170),
      ratio_claim("water-n2-vs-rsr-yoshida", "Water: N2 BAC (2) about 1.6 times more accurate than RSR4 SS3 Yoshida (best permutation)",
                  "4.3, Fig. 3", "fig3_water", "RSR4-SS3-Yoshida", "N2 BAC (2)", 1.6),
      {"water-best-reference",
       "Water: the best 4th-order reference scheme (Yoshida, Suzuki, McLachlan; best permutations) is RS4 S5 McLachlan CBA",
       "4.3, Fig. 4", "the smallest error constant among the 10 reference schemes of Fig. 4", {"accuracy"}, water_best_reference},
      ratio_claim("water-mclachlan-vs-n2", "Water: RS4 S5 McLachlan CBA about 4.7 times more accurate than N2 BAC (2)", "4.3, Fig. 4",
                  "fig5_water_dedicated", "N2 BAC (2)", "RS4-S5-McLachlan:CBA", 4.7),
      ratio_claim("water-r-vs-n2", "Water: R ABC (4) about 1.5 times more accurate than N2 BAC (2)", "4.3, Fig. 5",
                  "fig5_water_dedicated", "N2 BAC (2)", "R ABC (4)", 1.5),
      ratio_claim("water-p1-vs-n2", "Water: P1 BAC (5) about 8 times more accurate than N2 BAC (2)", "4.3, Fig. 5",
                  "fig5_water_dedicated", "N2 BAC (2)", "P1 BAC (5)", 8),
      ratio_claim("water-p1-vs-mclachlan", "Water: P1 BAC (5) about 1.7 times more accurate than RS4 S5 McLachlan CBA", "4.3, Fig. 5",
                  "fig5_water_dedicated", "RS4-S5-McLachlan:CBA", "P1 BAC (5)", 1.7),
      {"water-p1-time-saving",
       "Water: P1 BAC (5) decreases the computation time by 12 % against RS4 S5 McLachlan CBA (equal accuracy)",
       "4.3, after eq. (76)", "1 − (K_P/K_M)^(1/4) at equal h/C within 5 points of 12 %", {"accuracy"}, p1_time_saving},
      {"water-dedicated-time-savings",
       "Water: the dedicated N, R and P integrators do not decrease the computation time significantly against the reference schemes",
       "4.3, end", "the largest saving against RS4 S5 McLachlan CBA at equal accuracy and equal h/C below 25 %", {"accuracy"},
       dedicated_time_savings},
      {"fitted-slopes", "All dedicated and reference 4th-order schemes show slope 4 on Figs. 1, 3-5 (leapfrogs slope 2)",
       "4.2-4.3, Figs. 1, 3-5", "fitted log-log slope over the three finest h within " + runs::fixed_text(slope_tolerance, 1) + " of the order",
       {"accuracy"}, fitted_slopes},

      // Maps (map-N.jsonl, map-P.jsonl).
      map_claim("map-n-some-bodies", "N beats RS4 S5 McLachlan (best permutations, × (12/9)^4) only for some bodies of the triangle",
                "5.2, Fig. 8", "a fraction of the bodies with ratio > 1 strictly between 0 and 50 %", "N", n_wins_somewhere),
      map_claim("map-n-near-tops", "RS4 S5 McLachlan is especially more accurate than N near the symmetric tops", "5.2, Fig. 8",
                "median log10 ratio lower for δ < 1/9 than for δ ≥ 2/9 (δ = distance to the tops); the wins' shares are shown", "N",
                reference_best_near_tops),
      map_claim("map-p-asymmetric", "P beats RS4 S5 McLachlan (× (12/11)^4) only for very asymmetric bodies", "5.3, Fig. 10",
                "P wins somewhere, never near the tops (δ < 1/9)", "P", p_wins_far_from_tops),
      map_claim("map-p-singular", "The P map (Fig. 9) has isolated points where a singularity occurs in the automatic resolution",
                "5.3, Fig. 9", "singular bodies exist and none has a singular neighbour on the grid (their positions in the paper cannot be read)",
                "P", singular_points_isolated),
  };
  // Measured map ratios (maps-truth/measured-ratios.csv), per family.
  add_truth_claims(c, "N");
  add_truth_claims(c, "P");
  return c;
}

}  // namespace rotlie::reports
