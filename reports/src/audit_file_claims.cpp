// The audit's claims checked on the files of this report run: one row per statement of LV (2018),
// sections 4 and 5. The claims table at the end is data (the paper's value, where it is stated, the
// tolerance, the measurement and its arguments); the measurements above it read a file this run
// wrote and are shared by the rows (a solutions count, the ratio of two curves, a paper table
// against ours, a map's bands, …). The paper's tables are quoted in lv_paper_tables.hpp.
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

constexpr double ratio_tolerance = 0.20;  // the accuracy section's criterion for the paper's "about N times"
constexpr double slope_tolerance = 0.1;
constexpr double two_decimals = 0.005 + 1e-9;  // equal to a value printed with two decimals
const std::string quick_skips_r_and_p = "not computed in this run (section dedicated skips R and P with --quick)";

bool is_leapfrog(const std::string& name) { return name.rfind("ABCBA2", 0) == 0 || name.rfind("RSR2", 0) == 0; }

// A paper's table against ours, row by row: how many rows are within tolerance, the largest
// deviation (the last row of that size), and every row's deviation (NaN where ours is missing).
struct deviations {
  int within = 0;
  double worst = 0;
  std::string worst_name;
  std::vector<double> all;
  void add(const std::string& name, double deviation, double tolerance) {
    within += std::abs(deviation) <= tolerance;
    if (std::abs(deviation) >= std::abs(worst)) worst = deviation, worst_name = name;
    all.push_back(deviation);
  }
  void add_missing() { all.push_back(std::numeric_limits<double>::quiet_NaN()); }
};

// The paper's table named in a row: (integrator, value) pairs.
std::vector<std::pair<std::string, double>> paper_table(const std::string& name) {
  std::vector<std::pair<std::string, double>> t;
  if (name == "Table 3 analytic")
    for (const auto& r : lv_table3) t.emplace_back(r.integrator, r.analytic);
  else if (name == "Table 3 numeric")
    for (const auto& r : lv_table3) t.emplace_back(r.integrator, r.numeric);
  else if (name == "Table 4")
    for (const auto& r : lv_table4) t.emplace_back(r.integrator, r.analytic_e2);
  else
    throw std::logic_error("no paper table '" + name + "'");
  return t;
}

std::vector<std::string> paper_names(const std::string& table) {
  std::vector<std::string> names;
  for (const auto& [name, value] : paper_table(table)) names.push_back(name);
  return names;
}

// The names of the first entries of a ranking, as many as the paper names (fewer if there are fewer).
template <class Ranking, class Name>
std::vector<std::string> leading_names(const Ranking& ranking, const claim& c, Name name) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < std::min(c.expected.names.size(), ranking.size()); ++k) names.push_back(name(ranking[k]));
  return names;
}

// ---------------------------------------------------------------- solutions files (dedicated section)

// args: file, "quick-skips" when --quick leaves the file out. The number of real solutions.
measurement solution_count(report_files& f, const claim& c) {
  if (c.args.size() > 1 && f.quick()) return measurement::absent(quick_skips_r_and_p);
  const auto* j = f.json(c.args[0]);
  if (!j) return measurement::absent(c.args[0] + " missing");
  const auto n = j->at("solutions").size();
  return measurement::of(static_cast<double>(n), std::to_string(n) + " real solutions");
}

// args: paper table, file, normaliser ("" for none), scale, unit. Each solution's ‖H_R5‖ (over the
// normaliser's, times the scale) minus the paper's value.
measurement analytic_remainders(report_files& f, const claim& c) {
  const auto& file = c.args[1];
  const auto& normaliser = c.args[2];
  const double scale = std::stod(c.args[3]);
  const auto* j = f.json(file);
  if (!j) return measurement::absent(file + " missing");
  double unit = 1;
  if (!normaliser.empty()) {
    const auto* n = find_solution_named(*j, normaliser);
    if (!n) return measurement::absent(normaliser + " missing in " + file);
    unit = n->at("analytic_remainder").get<double>();
  }
  const auto table = paper_table(c.args[0]);
  deviations d;
  for (const auto& [name, paper] : table)
    if (const auto* s = find_solution_named(*j, name))
      d.add(name, scale * s->at("analytic_remainder").get<double>() / unit - paper, c.expected.tolerance);
    else
      d.add_missing();
  return measurement::of_deviations(d.all, std::to_string(d.within) + " of " + std::to_string(table.size()) + " equal; largest difference " +
                                               runs::significant_text(d.worst, 2) + c.args[4] + " (" + d.worst_name + ")");
}

// Every solution of a file by ‖H_R5‖, smallest first.
std::vector<std::pair<double, std::string>> by_remainder(const nlohmann::json& file) {
  std::vector<std::pair<double, std::string>> all;
  for (const auto& s : file.at("solutions")) all.emplace_back(s.at("analytic_remainder").get<double>(), solution_name(s));
  std::sort(all.begin(), all.end());
  return all;
}

// args: file. The names of as many smallest ‖H_R5‖ as the paper lists; the text says which differ.
measurement smallest_remainder_set(report_files& f, const claim& c) {
  const auto* j = f.json(c.args[0]);
  if (!j) return measurement::absent(c.args[0] + " missing");
  const auto names = leading_names(by_remainder(*j), c, [](const auto& r) { return r.second; });
  std::set<std::string> ours(names.begin(), names.end());
  std::string extra, missing;
  for (const auto& name : c.expected.names) {
    if (!ours.count(name)) missing += (missing.empty() ? "" : ", ") + name;
    ours.erase(name);
  }
  for (const auto& n : ours) extra += (extra.empty() ? "" : ", ") + n;
  return measurement::of_names(names, missing.empty() && extra.empty() ? "the same " + std::to_string(names.size())
                                                                      : "not in rotlie's " + std::to_string(names.size()) + ": " +
                                                                            (missing.empty() ? "none" : missing) + "; in rotlie's " +
                                                                            std::to_string(names.size()) +
                                                                            " only: " + (extra.empty() ? "none" : extra));
}

// args: file. The two smallest ‖H_R5‖, in order, with their values in units of 1e-2.
measurement two_smallest_remainders(report_files& f, const claim& c) {
  const auto* j = f.json(c.args[0]);
  if (!j) return measurement::absent(c.args[0] + " missing");
  const auto all = by_remainder(*j);
  if (all.size() < 2) return measurement::absent("fewer than two solutions in " + c.args[0]);
  return measurement::of_names({all[0].second, all[1].second},
                               all[0].second + " (" + runs::significant_text(100 * all[0].first, 3) + "e-2), " + all[1].second + " (" +
                                   runs::significant_text(100 * all[1].first, 3) + "e-2)");
}

// args: integrator. The fewest significant digits its coefficients share with those the paper
// prints (lv_printed_coefficients).
measurement printed_digits(report_files& f, const claim& c) {
  const auto& integrator = c.args[0];
  std::string file;
  for (const auto& e : lv_printed_coefficients)
    if (e.integrator == integrator) file = e.file;
  if (integrator[0] == 'P' && f.quick()) return measurement::absent("not computed in this run (section dedicated skips P with --quick)");
  const auto* j = f.json(file);
  const auto* s = j ? find_solution_named(*j, integrator) : nullptr;
  if (!s) return measurement::absent(integrator + " missing in " + file);
  double least = 45;
  std::string v;
  for (const auto& e : lv_printed_coefficients)
    if (e.integrator == integrator) {
      if (!(s->contains("coefficients") && s->at("coefficients").contains(e.coefficient)))
        return measurement::absent(integrator + " has no " + e.coefficient + " in " + file);
      const double d = agreeing_digits(s->at("coefficients").at(e.coefficient).get<std::string>(), e.paper);
      least = std::min(least, d);
      v += (v.empty() ? "" : ", ") + std::string(e.coefficient) + ": " + runs::fixed_text(d, 1);
    }
  return measurement::of(least, "agreeing digits " + v);
}

// args: file, integrator. Every stage coefficient > 0.
measurement positive_coefficients(report_files& f, const claim& c) {
  const auto* j = f.json(c.args[0]);
  const auto* s = j ? find_solution_named(*j, c.args[1]) : nullptr;
  if (!s) return measurement::absent(c.args[1] + " missing in " + c.args[0]);
  bool positive = true;
  std::string v;
  for (const auto& [k, text] : s->at("coefficients").items()) {
    const bool p = positive_decimal(text.get<std::string>());
    positive = positive && p;
    v += (v.empty() ? "" : ", ") + k + (p ? " > 0" : " ≤ 0");
  }
  return measurement::of_flag(positive, v);
}

// args: solutions file, chart. Among the paper table's (Table 4) integrators, the favourite by ‖H_R5‖
// and the best by the chart's error constants, with Spearman's ρ of the two.
measurement analytic_and_numeric_favourites(report_files& f, const claim& c) {
  const auto* water = f.json(c.args[0]);
  if (!water) return measurement::absent(c.args[0] + " missing");
  const auto* d = f.chart(c.args[1]);
  if (!d) return measurement::absent(c.args[1] + ".csv missing");
  std::vector<double> analytic, numeric;
  std::string analytic_best, numeric_best;
  double a_min = 1e300, n_min = 1e300;
  for (const auto& name : paper_names("Table 4")) {
    const auto* s = find_solution_named(*water, name);
    const auto* curve = series(*d, name);
    if (!s || !curve) continue;
    analytic.push_back(s->at("analytic_remainder").get<double>());
    numeric.push_back(fit(*curve, 4).constant);
    if (analytic.back() < a_min) a_min = analytic.back(), analytic_best = name;
    if (numeric.back() < n_min) n_min = numeric.back(), numeric_best = name;
  }
  return measurement::of_names({analytic_best, numeric_best},
                               "analytic favourite " + analytic_best + ", numeric best " + numeric_best +
                                   "; Spearman ρ (analytic, numeric) = " + runs::fixed_text(rank_correlation(analytic, numeric), 3) +
                                   " over " + std::to_string(analytic.size()));
}

// ---------------------------------------------------------------- accuracy curves (LV 4.2-4.3)

// args: chart, worse, better. "X about N times more accurate than Y": the ratio of the two curves'
// error constants.
measurement curve_ratio(report_files& f, const claim& c) {
  const auto &file = c.args[0], &worse = c.args[1], &better = c.args[2];
  const auto* d = f.chart(file);
  const auto* w = d ? series(*d, worse) : nullptr;
  const auto* b = d ? series(*d, better) : nullptr;
  if (!w || !b) return measurement::absent("curve missing in " + file + ".csv");
  const double ours = fit(*w, 4).constant / fit(*b, 4).constant, paper = c.expected.paper;
  return measurement::of(ours, runs::significant_text(ours, 3) + "× (" + series_name(*d, better) + " vs " + series_name(*d, worse) + ", " +
                                   runs::fixed_text(100 * (ours / paper - 1), 1) + " % from the paper)");
}

// One N curve of a chart among all its N curves: their fits, smallest first, and its own constant
// over the smallest.
struct n_standing {
  std::vector<std::pair<std::string, curve_fit>> fits;
  double mine = 0;
  double to_smallest() const { return mine / fits.front().second.constant; }
};

std::optional<n_standing> standing_of(report_files& f, const std::string& file, const std::string& name) {
  const auto* d = f.chart(file);
  const auto* c = d ? series(*d, name) : nullptr;
  if (!c) return std::nullopt;
  return n_standing{n_fits(*d), fit(*c, 4).constant};
}

// args: chart, integrator. Its error constant over the smallest of the chart's N curves.
measurement constant_over_best_n(report_files& f, const claim& c) {
  const auto &file = c.args[0], &name = c.args[1];
  const auto s = standing_of(f, file, name);
  if (!s) return measurement::absent(name + " missing in " + file + ".csv");
  return measurement::of(s->to_smallest(), "smallest: " + s->fits.front().first + "; " + name + " at " + runs::fixed_text(s->to_smallest(), 2) +
                                               "× its error at equal h/C" + f.quick_note());
}

// args: chart, integrator, its short name. The same, with the runner-up.
measurement constant_over_best_n_with_next(report_files& f, const claim& c) {
  const auto &file = c.args[0], &name = c.args[1], &short_name = c.args[2];
  const auto s = standing_of(f, file, name);
  if (!s) return measurement::absent(name + " missing in " + file + ".csv");
  std::string runner_up;
  for (const auto& [n, fitted] : s->fits)
    if (n != name && runner_up.empty()) runner_up = n + " at " + runs::fixed_text(fitted.constant / s->mine, 3) + "× " + short_name + "'s";
  return measurement::of(s->to_smallest(), "smallest: " + s->fits.front().first + "; " + short_name + " at " +
                                               runs::fixed_text(s->to_smallest(), 3) + "× the smallest; next " + runner_up + f.quick_note());
}

// args: paper table, chart, normaliser. Each integrator's error constant over the normaliser's,
// relative to the paper's ratio, minus 1.
measurement numeric_constants(report_files& f, const claim& c) {
  const auto &file = c.args[1], &normaliser = c.args[2];
  const auto* d = f.chart(file);
  const auto* n = d ? series(*d, normaliser) : nullptr;
  if (!n) return measurement::absent(normaliser + " missing in " + file + ".csv");
  const auto table = paper_table(c.args[0]);
  int found = 0;
  deviations dev;
  for (const auto& [name, paper] : table)
    if (const auto* curve = series(*d, name)) {
      ++found;
      dev.add(name, fit(*curve, 4).constant / fit(*n, 4).constant / paper - 1, c.expected.tolerance);
    } else {
      dev.add_missing();
    }
  return measurement::of_deviations(dev.all, std::to_string(dev.within) + " of " + std::to_string(table.size()) + " within tolerance (" +
                                                 std::to_string(found) + " found); largest deviation " + runs::fixed_text(100 * dev.worst, 1) +
                                                 " % (" + dev.worst_name + ")" + f.quick_note());
}

// args: chart, series. Spearman's ρ of the series' x and y.
measurement series_rank_correlation(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  const auto* s = d ? series(*d, c.args[1]) : nullptr;
  if (!s) return measurement::absent("series " + c.args[1] + " missing in " + c.args[0] + ".csv");
  const double rho = rank_correlation(s->x, s->y);
  return measurement::of(rho, "Spearman ρ = " + runs::fixed_text(rho, 3) + " over " + std::to_string(s->x.size()) + " solutions");
}

// args: chart. The N curves of smallest error constant, as many as the paper names.
measurement best_n_curves(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  if (!d) return measurement::absent(c.args[0] + ".csv missing");
  const auto fits = n_fits(*d);
  const auto names = leading_names(fits, c, [](const auto& fitted) { return fitted.first; });
  std::string v = "ranked by error/(h/C)^4: ";
  for (std::size_t k = 0; k < std::min<std::size_t>(3, fits.size()); ++k)
    v += (k ? ", " : "") + fits[k].first + " (" + runs::significant_text(fits[k].second.constant, 3) + ")";
  return measurement::of_names(names, v + f.quick_note());
}

// args: chart. The N curve of smallest error at the finest h, then those at the other h (each once).
measurement best_n_by_step(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  if (!d) return measurement::absent(c.args[0] + ".csv missing");
  std::vector<std::string> n, others;
  for (const auto& name : d->names)
    if (name[0] == 'N') n.push_back(name);
  if (n.empty()) return measurement::absent("no N curve in " + c.args[0] + ".csv");
  const std::size_t levels = d->series.at(n.front()).x.size();
  std::string v, finest;
  for (std::size_t i = 0; i < levels; ++i) {
    std::string best;
    double e = std::numeric_limits<double>::infinity();
    for (const auto& name : n) {
      const auto& curve = d->series.at(name);
      if (i < curve.y.size() && curve.y[i] < e) e = curve.y[i], best = name;
    }
    if (i + 1 == levels) finest = best;
    else if (std::find(others.begin(), others.end(), best) == others.end()) others.push_back(best);
    v += (i ? "; " : "") + std::string("h=2^-") + std::to_string(i + 1) + ": " + best;
  }
  others.insert(others.begin(), finest);
  return measurement::of_names(others, v);
}

// args: chart. The reference scheme (a name with its permutation) of smallest error constant.
measurement best_reference(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  if (!d) return measurement::absent(c.args[0] + ".csv missing");
  std::vector<std::pair<double, std::string>> refs;
  for (const auto& n : d->names)
    if (n.find(':') != std::string::npos) refs.emplace_back(fit(d->series.at(n), 4).constant, n);
  if (refs.empty()) return measurement::absent("no reference scheme in " + c.args[0] + ".csv");
  std::sort(refs.begin(), refs.end());
  return measurement::of_names({refs[0].second},
                               "best: " + refs[0].second +
                                   (refs.size() > 1 ? "; next " + refs[1].second + " at " + runs::fixed_text(refs[1].first / refs[0].first, 2) + "×"
                                                    : std::string()));
}

// Computing time saved at equal accuracy: error = K (h/C)^4, so the time ratio is (K / K_against)^(1/4).
double time_saved(const chart_curve& scheme, const chart_curve& against) {
  return 1 - std::pow(fit(scheme, 4).constant / fit(against, 4).constant, 0.25);
}

// args: chart, scheme, against. The time it saves against the other.
measurement time_saving(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  const auto* p = d ? series(*d, c.args[1]) : nullptr;
  const auto* m = d ? series(*d, c.args[2]) : nullptr;
  if (!p || !m) return measurement::absent("curve missing in " + c.args[0] + ".csv");
  const double saved = time_saved(*p, *m);
  return measurement::of(saved, percent(saved) + " at equal h/C");
}

// args: chart, against, schemes… The largest time saving among the schemes.
measurement largest_time_saving(report_files& f, const claim& c) {
  const auto* d = f.chart(c.args[0]);
  const auto* m = d ? series(*d, c.args[1]) : nullptr;
  if (!m) return measurement::absent("curve missing in " + c.args[0] + ".csv");
  double best = -1e9;
  std::string v;
  for (std::size_t k = 2; k < c.args.size(); ++k) {
    const auto* curve = series(*d, c.args[k]);
    if (!curve) continue;
    const double saved = time_saved(*curve, *m);
    best = std::max(best, saved);
    v += (v.empty() ? "" : "; ") + c.args[k] + ": " + percent(saved);
  }
  return measurement::of(best, v + " (negative: slower)");
}

// args: charts. Every curve's fitted slope minus its order (2 for the leapfrogs, else 4).
measurement fitted_slopes(report_files& f, const claim& c) {
  std::vector<double> all;
  int within = 0;
  double worst = 0;
  std::string worst_name;
  for (const auto& file : c.args) {
    const auto* d = f.chart(file);
    if (!d) continue;
    for (const auto& n : d->names) {
      const double order = is_leapfrog(n) ? 2 : 4, dev = fit(d->series.at(n), 4).slope - order;
      all.push_back(dev);
      within += std::abs(dev) <= c.expected.tolerance;
      if (std::abs(dev) > std::abs(worst)) worst = dev, worst_name = n + " (" + file + ")";
    }
  }
  return measurement::of_deviations(all, std::to_string(within) + " of " + std::to_string(all.size()) +
                                             " curves within tolerance; largest deviation " + runs::fixed_text(worst, 2) + " at " + worst_name +
                                             f.quick_note());
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

// The map of the row's family (args: family), or why there is none.
const audit_map* family_map(report_files& f, const claim& c, std::string& missing) {
  const auto* m = f.map(c.args[0]);
  if (!m) missing = "map-" + c.args[0] + ".jsonl missing";
  return m;
}

// args: family. The share of the bodies where the family beats the reference, with the first five.
measurement map_win_share(report_files& f, const claim& c) {
  std::string missing;
  const auto* m = family_map(f, c, missing);
  if (!m) return measurement::absent(missing);
  const auto b = band_counts(*m);
  const double fraction = b.total ? static_cast<double>(b.total_wins) / b.total : 0;
  std::string where;
  int listed = 0;
  for (const auto& x : m->bodies)
    if (x.ratio && *x.ratio > 1 && listed++ < 5)
      where += (where.empty() ? "" : ", ") + std::string("(") + runs::significant_text(x.I1, 3) + ", " + runs::significant_text(x.I2, 3) + "; δ " +
               runs::significant_text(asymmetry(x), 2) + "; " + x.best + ")";
  return measurement::of(fraction, c.args[0] + " better at " + share(b.total_wins, b.total) + (where.empty() ? "" : ": (I1, I2) = " + where) +
                                       grid(*m));
}

// args: family. The median log10 ratio near the tops minus that of the very asymmetric bodies.
measurement map_near_minus_far(report_files& f, const claim& c) {
  std::string missing;
  const auto* m = family_map(f, c, missing);
  if (!m) return measurement::absent(missing);
  const auto b = band_counts(*m);
  const double near = median(b.log_ratio[0]), far = median(b.log_ratio[2]);
  return measurement::of(near - far, "median log10 ratio " + runs::fixed_text(near, 2) + " near the tops, " +
                                         runs::fixed_text(median(b.log_ratio[1]), 2) + " in between, " + runs::fixed_text(far, 2) +
                                         " very asymmetric; " + c.args[0] + " wins " + share(b.wins[0], b.n[0]) + " near, " +
                                         share(b.wins[2], b.n[2]) + " far" + grid(*m));
}

// args: family. The family wins somewhere, never near the tops.
measurement map_wins_away_from_tops(report_files& f, const claim& c) {
  std::string missing;
  const auto* m = family_map(f, c, missing);
  if (!m) return measurement::absent(missing);
  const auto b = band_counts(*m);
  return measurement::of_flag(b.total_wins > 0 && b.wins[0] == 0,
                              c.args[0] + " wins " + share(b.wins[0], b.n[0]) + " near the tops, " + share(b.wins[1], b.n[1]) + " in between, " +
                                  share(b.wins[2], b.n[2]) + " very asymmetric; median log10 ratio " +
                                  runs::fixed_text(median(b.log_ratio[0]), 2) + ", " + runs::fixed_text(median(b.log_ratio[1]), 2) + ", " +
                                  runs::fixed_text(median(b.log_ratio[2]), 2) + grid(*m));
}

// args: family. Singular bodies exist and none has a singular neighbour on the grid.
measurement map_singular_isolated(report_files& f, const claim& c) {
  std::string missing;
  const auto* m = family_map(f, c, missing);
  if (!m) return measurement::absent(missing);
  std::set<std::pair<int, int>> singular;
  std::string v;
  for (const auto& x : m->bodies)
    if (x.singular) {
      singular.insert({x.i, x.j});
      v += (v.empty() ? "" : ", ") + std::string("(") + runs::significant_text(x.I1, 3) + ", " + runs::significant_text(x.I2, 3) + ")";
    }
  bool isolated = true;
  for (const auto& [i, j] : singular)
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        if ((di || dj) && singular.count({i + di, j + dj})) isolated = false;
  return measurement::of_flag(!singular.empty() && isolated, std::to_string(singular.size()) + " singular bod" +
                                                                 (singular.size() == 1 ? "y" : "ies") +
                                                                 (v.empty() ? "" : " at (I1, I2) = " + v) + grid(*m));
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

// The measured ratios of the row's family (args: family), at least three bodies, or why there are none.
std::optional<measured_ratios> family_ratios(report_files& f, const claim& c, std::string& missing) {
  const auto* t = f.csv(truth_file);
  if (!t) {
    missing = truth_file + " missing";
    return std::nullopt;
  }
  auto r = read_measured_ratios(*t, c.args[0]);
  if (r.analytic.size() < 3) {
    missing = "fewer than 3 measured " + c.args[0] + " bodies in " + truth_file;
    return std::nullopt;
  }
  return r;
}

// args: family. Spearman's ρ of the analytic and measured ratios.
measurement measured_ratio_correlation(report_files& f, const claim& c) {
  std::string missing;
  const auto r = family_ratios(f, c, missing);
  if (!r) return measurement::absent(missing);
  const double rho = rank_correlation(r->analytic, r->measured);
  return measurement::of(rho, "Spearman ρ = " + runs::fixed_text(rho, 3) + " over " + std::to_string(r->analytic.size()) + " bodies");
}

// args: family. The share of bodies whose verdict (ratio > 1) the measurement flips.
measurement measured_verdict_flips(report_files& f, const claim& c) {
  std::string missing;
  const auto r = family_ratios(f, c, missing);
  if (!r) return measurement::absent(missing);
  const auto n = static_cast<int>(r->analytic.size());
  return measurement::of(static_cast<double>(r->flipped) / n, "flips at " + share(r->flipped, n));
}

// ---------------------------------------------------------------- rows built from the same pattern

claim ratio_row(std::string id, std::string statement, std::string where, std::string chart, std::string worse, std::string better,
                double paper) {
  return {std::move(id),
          std::move(statement),
          std::move(where),
          "our ratio of error/(h/C)^4 (three finest h) within " + percent(ratio_tolerance) + " of " + runs::significant_text(paper, 3) + "×",
          {"accuracy"},
          relative_within(paper, ratio_tolerance),
          curve_ratio,
          {std::move(chart), std::move(worse), std::move(better)}};
}

claim digits_row(std::string id, const std::string& integrator, std::string where) {
  return {std::move(id), "The coefficients of " + integrator + " printed with 41 digits", std::move(where),
          "each agrees with rotlie's 40-digit certified value to ≥ 38 significant digits", {"dedicated"}, at_least(38), printed_digits,
          {integrator}};
}

}  // namespace

std::vector<audit_claim<report_files>> file_claims() {
  const std::string n_vs_mclachlan = "N beats RS4 S5 McLachlan (best permutations, × (12/9)^4) only for some bodies of the triangle";
  // id, statement (LV), where, tolerance, sections read, the paper's value and comparison, measurement, its arguments.
  std::vector<claim> c = {
      // Dedicated section: the solver's solutions.
      {"sphere-n-count", "Spherical top: the N integrators have 12 real solutions", "4.2, Table 2", "the same count, exactly",
       {"dedicated"}, equal_to(12), solution_count, {"solutions_sphere.json"}},
      {"table3-analytic", "Table 3, analytic column: ‖H_R5‖ normalised by N5 (2) (1 to 991.42)", "4.2, Table 3",
       "every ratio equal to the paper's to its two printed decimals (±0.005)", {"dedicated"}, each_within(two_decimals),
       analytic_remainders, {"Table 3 analytic", "solutions_sphere.json", "N5 ABC (2)", "1", ""}},
      {"water-n-count", "Water: the N integrators have 90 real solutions over the six permutations", "4.3", "the same count, exactly",
       {"dedicated"}, equal_to(90), solution_count, {"solutions_water.json"}},
      {"table4-members", "Table 4 lists the 15 N integrators of smallest analytic remainder for water", "4.3, Table 4",
       "rotlie's 15 smallest ‖H_R5‖ are the same 15 integrators", {"dedicated"}, same_name_set(paper_names("Table 4")),
       smallest_remainder_set, {"solutions_water.json"}},
      {"table4-values", "Table 4: analytic remainders from 1.06e-2 (N2 BAC (2)) to 3.83e-2 (N1 ABC (2))", "4.3, Table 4",
       "every value equal to the paper's to its printed digits (±0.005e-2)", {"dedicated"}, each_within(two_decimals),
       analytic_remainders, {"Table 4", "solutions_water.json", "", "100", "e-2"}},
      {"water-smallest-remainders", "Water: the smallest analytic remainders are N2 BAC (2), then N2 ACB (1)", "4.3, Table 4",
       "rotlie's first two by ‖H_R5‖", {"dedicated"}, same_names({"N2 BAC (2)", "N2 ACB (1)"}), two_smallest_remainders,
       {"solutions_water.json"}},
      digits_row("eq74-digits", "N2 BAC (2)", "4.3, eq. (74)"),
      digits_row("eq76-digits", "P1 BAC (5)", "4.3, eq. (76)"),
      {"n2-positive", "Water: all the coefficients of N2 BAC (2) are positive", "4.3, after eq. (74)",
       "every stage coefficient > 0 (the second half cites Sheng 1989, Suzuki 1991: not checked)", {"dedicated"}, property_holds(),
       positive_coefficients, {"solutions_water.json", "N2 BAC (2)"}},
      {"sheng-suzuki", "All-positive coefficients are impossible for a classical 4th-order splitting (Sheng 1989; Suzuki 1991)",
       "4.3, after eq. (74)", "—", {}, cannot_be_checked(), nullptr, {"a theorem the paper cites, not a number of rotlie's"}},
      {"table4-numeric-choice", "Table 4's analytic remainders are very close, so the best N for water has to be chosen numerically",
       "4.3, Table 4, Fig. 3",
       "the analytic order of Table 4's 15 N differs from the numeric order at the top (the favourites differ)", {"dedicated", "accuracy"},
       names_differ(), analytic_and_numeric_favourites, {"solutions_water.json", "fig3_water"}},
      {"water-r-count", "Water: the integrator R has 46 real solutions over the six permutations", "4.3", "the same count, exactly",
       {"dedicated"}, equal_to(46), solution_count, {"solutions_water_R.json", "quick-skips"}},
      {"water-p-count", "Water: the fifteen integrators P have 724 real solutions in total", "4.3", "the same count, exactly",
       {"dedicated"}, equal_to(724), solution_count, {"solutions_water_P.json", "quick-skips"}},

      // Accuracy section: the curves of Figs. 1-5.
      {"sphere-best-n", "Spherical top: the best N integrator is N5 (2)", "4.2, Fig. 1, Table 3",
       "N5 (2)'s error constant within 5 % of the smallest among the 12 N solutions", {"accuracy"}, at_most(1.05),
       constant_over_best_n_with_next, {"fig1_sphere", "N5 ABC (2)", "N5 (2)"}},
      ratio_row("sphere-n5-vs-yoshida", "Spherical top: N5 (2) about 700 times more accurate than ABCBA4 SS3 Yoshida at equal h/C",
                "4.2, Fig. 1", "fig1_sphere", "ABCBA4-SS3-Yoshida", "N5 ABC (2)", 700),
      {"table3-numeric", "Table 3, numeric column: the 11 numeric remainders normalised by N5 (2) (1.00 to 1120.50)", "4.2, Table 3",
       "every ratio within " + percent(ratio_tolerance) + " of the paper's", {"accuracy"}, each_within(ratio_tolerance),
       numeric_constants, {"Table 3 numeric", "fig1_sphere", "N5 ABC (2)"}},
      {"sphere-remainders-correlated",
       "The analytic remainder is very well correlated with the numeric one (spherical top, 11 N solutions)", "4.2, Fig. 2",
       "Spearman rank correlation ≥ 0.9 between rotlie's analytic and numeric ratios", {"accuracy"}, at_least(0.9),
       series_rank_correlation, {"fig2_sphere_remainders", "rotlie"}},
      {"water-two-best-n",
       "Water: the numerically best N integrators are N2 BAC (2) and N2 ACB (1) (the two smallest analytic remainders of Table 4)",
       "4.3, Fig. 3", "the two smallest error constants among Table 4's 15 N are these two", {"accuracy"},
       same_name_set({"N2 BAC (2)", "N2 ACB (1)"}), best_n_curves, {"fig3_water"}},
      {"water-best-n-by-step", "Water: at the smallest step N2 BAC (2) is the best N, at the other steps N2 ACB (1)", "4.3, Fig. 3",
       "the N with the smallest error at each h = 2^-i of the run", {"accuracy"}, same_names({"N2 BAC (2)", "N2 ACB (1)"}),
       best_n_by_step, {"fig3_water"}},
      {"water-best-n", "Water: the best N integrator is N2 BAC (2) (the paper's choice, eq. 73)", "4.3, Fig. 3",
       "N2 BAC (2)'s error constant within 5 % of the smallest among Table 4's 15 N", {"accuracy"}, at_most(1.05),
       constant_over_best_n, {"fig3_water", "N2 BAC (2)"}},
      ratio_row("water-n2-vs-yoshida", "Water: N2 BAC (2) about 170 times more accurate than ABCBA4 SS3 Yoshida (best permutation)",
                "4.3, Fig. 3", "fig3_water", "ABCBA4-SS3-Yoshida", "N2 BAC (2)", 170),
      ratio_row("water-n2-vs-rsr-yoshida", "Water: N2 BAC (2) about 1.6 times more accurate than RSR4 SS3 Yoshida (best permutation)",
                "4.3, Fig. 3", "fig3_water", "RSR4-SS3-Yoshida", "N2 BAC (2)", 1.6),
      {"water-best-reference",
       "Water: the best 4th-order reference scheme (Yoshida, Suzuki, McLachlan; best permutations) is RS4 S5 McLachlan CBA",
       "4.3, Fig. 4", "the smallest error constant among the 10 reference schemes of Fig. 4", {"accuracy"},
       same_names({"RS4-S5-McLachlan:CBA"}), best_reference, {"fig4_water_reference"}},
      ratio_row("water-mclachlan-vs-n2", "Water: RS4 S5 McLachlan CBA about 4.7 times more accurate than N2 BAC (2)", "4.3, Fig. 4",
                "fig5_water_dedicated", "N2 BAC (2)", "RS4-S5-McLachlan:CBA", 4.7),
      ratio_row("water-r-vs-n2", "Water: R ABC (4) about 1.5 times more accurate than N2 BAC (2)", "4.3, Fig. 5", "fig5_water_dedicated",
                "N2 BAC (2)", "R ABC (4)", 1.5),
      ratio_row("water-p1-vs-n2", "Water: P1 BAC (5) about 8 times more accurate than N2 BAC (2)", "4.3, Fig. 5", "fig5_water_dedicated",
                "N2 BAC (2)", "P1 BAC (5)", 8),
      ratio_row("water-p1-vs-mclachlan", "Water: P1 BAC (5) about 1.7 times more accurate than RS4 S5 McLachlan CBA", "4.3, Fig. 5",
                "fig5_water_dedicated", "RS4-S5-McLachlan:CBA", "P1 BAC (5)", 1.7),
      {"water-p1-time-saving",
       "Water: P1 BAC (5) decreases the computation time by 12 % against RS4 S5 McLachlan CBA (equal accuracy)",
       "4.3, after eq. (76)", "1 − (K_P/K_M)^(1/4) at equal h/C within 5 points of 12 %", {"accuracy"}, absolute_within(0.12, 0.05),
       time_saving, {"fig5_water_dedicated", "P1 BAC (5)", "RS4-S5-McLachlan"}},
      {"water-dedicated-time-savings",
       "Water: the dedicated N, R and P integrators do not decrease the computation time significantly against the reference schemes",
       "4.3, end", "the largest saving against RS4 S5 McLachlan CBA at equal accuracy and equal h/C below 25 %", {"accuracy"},
       below(0.25), largest_time_saving, {"fig5_water_dedicated", "RS4-S5-McLachlan", "N2 BAC (2)", "R ABC (4)", "P1 BAC (5)"}},
      {"fitted-slopes", "All dedicated and reference 4th-order schemes show slope 4 on Figs. 1, 3-5 (leapfrogs slope 2)",
       "4.2-4.3, Figs. 1, 3-5", "fitted log-log slope over the three finest h within " + runs::fixed_text(slope_tolerance, 1) + " of the order",
       {"accuracy"}, each_within(slope_tolerance), fitted_slopes,
       {"fig1_sphere", "fig3_water", "fig4_water_reference", "fig5_water_dedicated"}},

      // Maps (map-N.jsonl, map-P.jsonl).
      {"map-n-some-bodies", n_vs_mclachlan, "5.2, Fig. 8", "a fraction of the bodies with ratio > 1 strictly between 0 and 50 %",
       {"maps"}, between_0_and(0.5), map_win_share, {"N"}},
      {"map-n-near-tops", "RS4 S5 McLachlan is especially more accurate than N near the symmetric tops", "5.2, Fig. 8",
       "median log10 ratio lower for δ < 1/9 than for δ ≥ 2/9 (δ = distance to the tops); the wins' shares are shown", {"maps"},
       below(0), map_near_minus_far, {"N"}},
      {"map-p-asymmetric", "P beats RS4 S5 McLachlan (× (12/11)^4) only for very asymmetric bodies", "5.3, Fig. 10",
       "P wins somewhere, never near the tops (δ < 1/9)", {"maps"}, property_holds(), map_wins_away_from_tops, {"P"}},
      {"map-p-singular", "The P map (Fig. 9) has isolated points where a singularity occurs in the automatic resolution", "5.3, Fig. 9",
       "singular bodies exist and none has a singular neighbour on the grid (their positions in the paper cannot be read)", {"maps"},
       property_holds(), map_singular_isolated, {"P"}},
  };
  // Measured map ratios (maps-truth/measured-ratios.csv), per family.
  for (const std::string family : {"N", "P"}) {
    c.push_back({"truth-correlation-" + family,
                 "The analytic remainder predicts the measured gain of the best " + family + " over RS4 S5 McLachlan (section 5 relies on it)",
                 "5 (from 4.2)", "Spearman rank correlation of analytic and measured (equal h/C) ratios ≥ 0.8", {"maps-truth"}, at_least(0.8),
                 measured_ratio_correlation, {family}});
    c.push_back({"truth-verdicts-" + family, "The analytic verdict \"" + family + " better than RS4 S5 McLachlan\" is the measured one",
                 "5.2-5.3, Figs. 8, 10", "the verdict (ratio > 1) flips at ≤ 10 % of the measured bodies", {"maps-truth"}, at_most(0.1),
                 measured_verdict_flips, {family}});
  }
  return c;
}

}  // namespace rotlie::reports
