// The audit rows read from the files of this report run (see audit_table.hpp). Paper values
// below are quotes of LV (2018), marked with the table or equation they come from; every rotlie
// value is read from a file the same run wrote.
#include "rotlie/reports/audit_table.hpp"

#include <algorithm>
#include <cln/integer.h>
#include <cln/integer_io.h>
#include <cln/rational.h>
#include <cln/real.h>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "rotlie/reports/lv_paper_tables.hpp"
#include "rotlie/reports/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report_csv_reader.hpp"

namespace rotlie::reports {
namespace {

namespace fs = std::filesystem;

constexpr double ratio_tolerance = 0.20;  // the accuracy section's criterion for the paper's "about N times"
constexpr double slope_tolerance = 0.1;
constexpr int fit_points = 3;  // as protocol_curves.cpp: the three finest steps

std::string percent(double x) { return fixed_text(100 * x, 1) + " %"; }

audit_row row(std::string statement, std::string where, std::string tolerance) {
  audit_row r;
  r.statement = std::move(statement);
  r.where = std::move(where);
  r.tolerance = std::move(tolerance);
  return r;
}

audit_row& judge(audit_row& r, bool holds, std::string value) {
  r.value = std::move(value);
  r.verdict = holds ? audit_verdict::holds : audit_verdict::does_not_hold;
  return r;
}

audit_row& not_computed(audit_row& r, const std::string& why) {
  r.verdict = audit_verdict::not_computed;
  r.why = why;
  r.value = "—";
  return r;
}

// error = constant (h/C)^order over the three finest points, as the accuracy section fits it.
struct curve_fit {
  double constant = 0, slope = 0;
};

curve_fit fit(const chart_curve& c, int order) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < c.x.size(); ++i) p.emplace_back(c.x[i], c.y[i]);
  std::sort(p.begin(), p.end());
  if (p.size() < static_cast<std::size_t>(fit_points)) throw std::runtime_error("a curve of fewer than three points");
  p.resize(fit_points);
  curve_fit f;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : p) {
    f.constant += y / std::pow(x, order) / fit_points;
    const double lx = std::log(x), ly = std::log(y);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  f.slope = (fit_points * sxy - sx * sy) / (fit_points * sxx - sx * sx);
  return f;
}

bool is_leapfrog(const std::string& name) { return name.rfind("ABCBA2", 0) == 0 || name.rfind("RSR2", 0) == 0; }

// The series whose name is `name` or starts with `name:` (a reference scheme at its best permutation).
const chart_curve* series(const chart_data& d, const std::string& name) {
  for (const auto& n : d.names)
    if (n == name || n.rfind(name + ":", 0) == 0) return &d.series.at(n);
  return nullptr;
}

std::string series_name(const chart_data& d, const std::string& name) {
  for (const auto& n : d.names)
    if (n == name || n.rfind(name + ":", 0) == 0) return n;
  return name;
}

class reader {
 public:
  explicit reader(const audit_inputs& in) : in_(in) {}

  bool ran(const std::string& key) const { return in_.sections_run.count(key) > 0; }

  const chart_data* chart(const std::string& file) {
    auto it = charts_.find(file);
    if (it == charts_.end()) it = charts_.emplace(file, read_chart_csv(in_.folder / (file + ".csv"))).first;
    return it->second ? &*it->second : nullptr;
  }

  const nlohmann::json* json(const std::string& file) {
    auto it = jsons_.find(file);
    if (it == jsons_.end()) {
      std::optional<nlohmann::json> j;
      std::ifstream f(in_.folder / file);
      if (f) {
        j = nlohmann::json::parse(f, nullptr, false);
        if (j->is_discarded()) throw std::runtime_error(printable_path(in_.folder / file) + " is not JSON");
      }
      it = jsons_.emplace(file, std::move(j)).first;
    }
    return it->second ? &*it->second : nullptr;
  }

  const audit_inputs& inputs() const { return in_; }

 private:
  const audit_inputs& in_;
  std::map<std::string, std::optional<chart_data>> charts_;
  std::map<std::string, std::optional<nlohmann::json>> jsons_;
};

// ---------------------------------------------------------------- accuracy section (LV 4.2-4.3)

void ratio_claim(std::vector<audit_row>& rows, reader& rd, const std::string& statement, const std::string& where,
                 const std::string& file, const std::string& worse, const std::string& better, double paper) {
  auto r = row(statement, where, "our ratio of error/(h/C)^4 (three finest h) within " + percent(ratio_tolerance) + " of " +
                                     significant_text(paper, 3) + "×");
  const auto* d = rd.ran("accuracy") ? rd.chart(file) : nullptr;
  const auto* w = d ? series(*d, worse) : nullptr;
  const auto* b = d ? series(*d, better) : nullptr;
  if (!w || !b) {
    rows.push_back(not_computed(r, rd.ran("accuracy") ? "curve missing in " + file + ".csv" : "not computed in this run (section accuracy)"));
    return;
  }
  const double ours = fit(*w, 4).constant / fit(*b, 4).constant;
  rows.push_back(judge(r, std::abs(ours / paper - 1) <= ratio_tolerance,
                       significant_text(ours, 3) + "× (" + series_name(*d, better) + " vs " + series_name(*d, worse) + ", " +
                           fixed_text(100 * (ours / paper - 1), 1) + " % from the paper)"));
}

// The N series of a chart (names "N<k> PERM (label)"), with their fits.
std::vector<std::pair<std::string, curve_fit>> n_fits(const chart_data& d) {
  std::vector<std::pair<std::string, curve_fit>> out;
  for (const auto& n : d.names)
    if (n.size() > 1 && n[0] == 'N' && std::isdigit(static_cast<unsigned char>(n[1]))) out.emplace_back(n, fit(d.series.at(n), 4));
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second.constant < b.second.constant; });
  return out;
}

void accuracy_rows(std::vector<audit_row>& rows, reader& rd) {
  const bool ran = rd.ran("accuracy");
  const std::string absent = "not computed in this run (section accuracy)";
  const std::string quick = rd.inputs().quick ? " (--quick: h down to 2^-8)" : "";

  // 4.2: the best N for the spherical top.
  {
    auto r = row("Spherical top: the best N integrator is N5 (2)", "4.2, Fig. 1, Table 3",
                 "N5 (2)'s error constant within 5 % of the smallest among the 12 N solutions");
    const auto* d = ran ? rd.chart("fig1_sphere") : nullptr;
    const auto* n5 = d ? series(*d, "N5 ABC (2)") : nullptr;
    if (!n5) rows.push_back(not_computed(r, ran ? "N5 ABC (2) missing in fig1_sphere.csv" : absent));
    else {
      const auto fits = n_fits(*d);
      const double mine = fit(*n5, 4).constant;
      std::string runner_up;
      for (const auto& [n, f] : fits)
        if (n != "N5 ABC (2)" && runner_up.empty()) runner_up = n + " at " + fixed_text(f.constant / mine, 3) + "× N5 (2)'s";
      rows.push_back(judge(r, mine <= 1.05 * fits.front().second.constant,
                           "smallest: " + fits.front().first + "; N5 (2) at " + fixed_text(mine / fits.front().second.constant, 3) +
                               "× the smallest; next " + runner_up + quick));
    }
  }
  ratio_claim(rows, rd, "Spherical top: N5 (2) about 700 times more accurate than ABCBA4 SS3 Yoshida at equal h/C",
              "4.2, Fig. 1", "fig1_sphere", "ABCBA4-SS3-Yoshida", "N5 ABC (2)", 700);

  {
    auto r = row("Table 3, numeric column: the 11 numeric remainders normalised by N5 (2) (1.00 to 1120.50)", "4.2, Table 3",
                 "every ratio within " + percent(ratio_tolerance) + " of the paper's");
    const auto* d = ran ? rd.chart("fig1_sphere") : nullptr;
    const auto* n5 = d ? series(*d, "N5 ABC (2)") : nullptr;
    if (!n5) rows.push_back(not_computed(r, ran ? "N5 ABC (2) missing in fig1_sphere.csv" : absent));
    else {
      int within = 0, found = 0;
      double worst = 0;
      std::string worst_name;
      for (const auto& paper : lv_table3) {
        const std::string name = paper.integrator;
        const double lv = paper.numeric;
        const auto* c = series(*d, name);
        if (!c) continue;
        ++found;
        const double dev = fit(*c, 4).constant / fit(*n5, 4).constant / lv - 1;
        within += std::abs(dev) <= ratio_tolerance;
        if (std::abs(dev) >= std::abs(worst)) worst = dev, worst_name = name;
      }
      rows.push_back(judge(r, within == static_cast<int>(lv_table3.size()),
                           std::to_string(within) + " of " + std::to_string(lv_table3.size()) + " within tolerance (" +
                               std::to_string(found) + " found); largest deviation " + fixed_text(100 * worst, 1) + " % (" +
                               worst_name + ")" + quick));
    }
  }
  {
    auto r = row("The analytic remainder is very well correlated with the numeric one (spherical top, 11 N solutions)",
                 "4.2, Fig. 2", "Spearman rank correlation ≥ 0.9 between rotlie's analytic and numeric ratios");
    const auto* d = ran ? rd.chart("fig2_sphere_remainders") : nullptr;
    const auto* ours = d ? series(*d, "rotlie") : nullptr;
    if (!ours) rows.push_back(not_computed(r, ran ? "series rotlie missing in fig2_sphere_remainders.csv" : absent));
    else {
      const double rho = rank_correlation(ours->x, ours->y);
      rows.push_back(judge(r, rho >= 0.9, "Spearman ρ = " + fixed_text(rho, 3) + " over " + std::to_string(ours->x.size()) + " solutions"));
    }
  }

  // 4.3, Fig. 3: the best N for water, by curve and by step.
  {
    auto r = row("Water: the numerically best N integrators are N2 BAC (2) and N2 ACB (1) (the two smallest analytic remainders of Table 4)",
                 "4.3, Fig. 3", "the two smallest error constants among Table 4's 15 N are these two");
    const auto* d = ran ? rd.chart("fig3_water") : nullptr;
    if (!d) rows.push_back(not_computed(r, absent));
    else {
      const auto fits = n_fits(*d);
      const bool ok = fits.size() >= 2 && ((fits[0].first == "N2 BAC (2)" && fits[1].first == "N2 ACB (1)") ||
                                           (fits[0].first == "N2 ACB (1)" && fits[1].first == "N2 BAC (2)"));
      std::string v = "ranked by error/(h/C)^4: ";
      for (std::size_t k = 0; k < std::min<std::size_t>(3, fits.size()); ++k)
        v += (k ? ", " : "") + fits[k].first + " (" + significant_text(fits[k].second.constant, 3) + ")";
      rows.push_back(judge(r, ok, v + quick));
    }
  }
  {
    auto r = row("Water: at the smallest step N2 BAC (2) is the best N, at the other steps N2 ACB (1)", "4.3, Fig. 3",
                 "the N with the smallest error at each h = 2^-i of the run");
    const auto* d = ran ? rd.chart("fig3_water") : nullptr;
    if (!d) rows.push_back(not_computed(r, absent));
    else {
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
      rows.push_back(judge(r, ok, v));
    }
  }
  {
    auto r = row("Water: the best N integrator is N2 BAC (2) (the paper's choice, eq. 73)", "4.3, Fig. 3",
                 "N2 BAC (2)'s error constant within 5 % of the smallest among Table 4's 15 N");
    const auto* d = ran ? rd.chart("fig3_water") : nullptr;
    const auto* n2 = d ? series(*d, "N2 BAC (2)") : nullptr;
    if (!n2) rows.push_back(not_computed(r, ran ? "N2 BAC (2) missing in fig3_water.csv" : absent));
    else {
      const auto fits = n_fits(*d);
      const double mine = fit(*n2, 4).constant;
      rows.push_back(judge(r, mine <= 1.05 * fits.front().second.constant,
                           "smallest: " + fits.front().first + "; N2 BAC (2) at " + fixed_text(mine / fits.front().second.constant, 2) +
                               "× its error at equal h/C" + quick));
    }
  }
  ratio_claim(rows, rd, "Water: N2 BAC (2) about 170 times more accurate than ABCBA4 SS3 Yoshida (best permutation)", "4.3, Fig. 3",
              "fig3_water", "ABCBA4-SS3-Yoshida", "N2 BAC (2)", 170);
  ratio_claim(rows, rd, "Water: N2 BAC (2) about 1.6 times more accurate than RSR4 SS3 Yoshida (best permutation)", "4.3, Fig. 3",
              "fig3_water", "RSR4-SS3-Yoshida", "N2 BAC (2)", 1.6);
  {
    auto r = row("Water: the best 4th-order reference scheme (Yoshida, Suzuki, McLachlan; best permutations) is RS4 S5 McLachlan CBA",
                 "4.3, Fig. 4", "the smallest error constant among the 10 reference schemes of Fig. 4");
    const auto* d = ran ? rd.chart("fig4_water_reference") : nullptr;
    if (!d) rows.push_back(not_computed(r, absent));
    else {
      std::vector<std::pair<double, std::string>> refs;
      for (const auto& n : d->names)
        if (n.find(':') != std::string::npos) refs.emplace_back(fit(d->series.at(n), 4).constant, n);
      std::sort(refs.begin(), refs.end());
      rows.push_back(judge(r, !refs.empty() && refs[0].second == "RS4-S5-McLachlan:CBA",
                           "best: " + refs[0].second + (refs.size() > 1 ? "; next " + refs[1].second + " at " +
                                                                            fixed_text(refs[1].first / refs[0].first, 2) + "×"
                                                                      : std::string())));
    }
  }
  ratio_claim(rows, rd, "Water: RS4 S5 McLachlan CBA about 4.7 times more accurate than N2 BAC (2)", "4.3, Fig. 4",
              "fig5_water_dedicated", "N2 BAC (2)", "RS4-S5-McLachlan:CBA", 4.7);
  ratio_claim(rows, rd, "Water: R ABC (4) about 1.5 times more accurate than N2 BAC (2)", "4.3, Fig. 5", "fig5_water_dedicated",
              "N2 BAC (2)", "R ABC (4)", 1.5);
  ratio_claim(rows, rd, "Water: P1 BAC (5) about 8 times more accurate than N2 BAC (2)", "4.3, Fig. 5", "fig5_water_dedicated",
              "N2 BAC (2)", "P1 BAC (5)", 8);
  ratio_claim(rows, rd, "Water: P1 BAC (5) about 1.7 times more accurate than RS4 S5 McLachlan CBA", "4.3, Fig. 5",
              "fig5_water_dedicated", "RS4-S5-McLachlan:CBA", "P1 BAC (5)", 1.7);

  // Computing time at equal accuracy: error = K (h/C)^4, so the time ratio is (K_P / K_M)^(1/4).
  {
    auto r = row("Water: P1 BAC (5) decreases the computation time by 12 % against RS4 S5 McLachlan CBA (equal accuracy)",
                 "4.3, after eq. (76)", "1 − (K_P/K_M)^(1/4) at equal h/C within 5 points of 12 %");
    const auto* d = ran ? rd.chart("fig5_water_dedicated") : nullptr;
    const auto* p = d ? series(*d, "P1 BAC (5)") : nullptr;
    const auto* m = d ? series(*d, "RS4-S5-McLachlan") : nullptr;
    if (!p || !m) rows.push_back(not_computed(r, absent));
    else {
      const double saved = 1 - std::pow(fit(*p, 4).constant / fit(*m, 4).constant, 0.25);
      rows.push_back(judge(r, std::abs(saved - 0.12) <= 0.05, percent(saved) + " at equal h/C"));
    }
  }
  {
    auto r = row("Water: the dedicated N, R and P integrators do not decrease the computation time significantly against the reference schemes",
                 "4.3, end", "the largest saving against RS4 S5 McLachlan CBA at equal accuracy and equal h/C below 25 %");
    const auto* d = ran ? rd.chart("fig5_water_dedicated") : nullptr;
    const auto* m = d ? series(*d, "RS4-S5-McLachlan") : nullptr;
    if (!m) rows.push_back(not_computed(r, absent));
    else {
      double best = -1e9;
      std::string v;
      for (const auto* name : {"N2 BAC (2)", "R ABC (4)", "P1 BAC (5)"}) {
        const auto* c = series(*d, name);
        if (!c) continue;
        const double saved = 1 - std::pow(fit(*c, 4).constant / fit(*m, 4).constant, 0.25);
        best = std::max(best, saved);
        v += (v.empty() ? "" : "; ") + std::string(name) + ": " + percent(saved);
      }
      rows.push_back(judge(r, best < 0.25, v + " (negative: slower)"));
    }
  }
  // Slopes: all the integrators of Figs. 1, 3-5 are of order 4, the leapfrogs of order 2.
  {
    auto r = row("All dedicated and reference 4th-order schemes show slope 4 on Figs. 1, 3-5 (leapfrogs slope 2)", "4.2-4.3, Figs. 1, 3-5",
                 "fitted log-log slope over the three finest h within " + fixed_text(slope_tolerance, 1) + " of the order");
    if (!ran) rows.push_back(not_computed(r, absent));
    else {
      int total = 0, within = 0;
      double worst = 0;
      std::string worst_name;
      for (const auto* file : {"fig1_sphere", "fig3_water", "fig4_water_reference", "fig5_water_dedicated"}) {
        const auto* d = rd.chart(file);
        if (!d) continue;
        for (const auto& n : d->names) {
          const double order = is_leapfrog(n) ? 2 : 4, dev = fit(d->series.at(n), 4).slope - order;
          ++total;
          within += std::abs(dev) <= slope_tolerance;
          if (std::abs(dev) > std::abs(worst)) worst = dev, worst_name = n + " (" + file + ")";
        }
      }
      rows.push_back(judge(r, total > 0 && within == total,
                           std::to_string(within) + " of " + std::to_string(total) + " curves within tolerance; largest deviation " +
                               fixed_text(worst, 2) + " at " + worst_name + quick));
    }
  }
}

// ---------------------------------------------------------------- dedicated section (solutions)

std::string solution_name(const nlohmann::json& s) {
  return s.at("scheme").get<std::string>() + " " + s.at("perm").get<std::string>() + " (" + std::to_string(s.at("label").get<int>()) + ")";
}

const nlohmann::json* find(const nlohmann::json& file, const std::string& name) {
  for (const auto& s : file.at("solutions"))
    if (solution_name(s) == name) return &s;
  return nullptr;
}

// "d.ddd…e-2" as an exact rational.
cln::cl_RA decimal(const std::string& text) {
  std::string digits;
  long exponent = 0, point = -1;
  bool negative = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '-' && i == 0) negative = true;
    else if (c == '.') point = static_cast<long>(digits.size());
    else if (c == 'e' || c == 'E') {
      exponent = std::stol(text.substr(i + 1));
      break;
    } else if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    else if (c != '+') throw std::runtime_error("'" + text + "' is not a decimal number");
  }
  if (digits.empty()) throw std::runtime_error("'" + text + "' is not a decimal number");
  const long fraction = point < 0 ? 0 : static_cast<long>(digits.size()) - point;
  const long shift = exponent - fraction;
  cln::cl_RA x = cln::cl_I(digits.c_str());
  x = shift >= 0 ? x * cln::expt_pos(cln::cl_I(10), cln::cl_I(shift)) : x / cln::expt_pos(cln::cl_I(10), cln::cl_I(-shift));
  return negative ? -x : x;
}

// How many significant digits two decimals share: −log10 |x − y| / |y|, at most 45.
double agreeing_digits(const std::string& ours, const std::string& paper) {
  const cln::cl_RA x = decimal(ours), y = decimal(paper);
  if (x == y) return 45;
  const double rel = cln::double_approx(cln::abs((x - y) / y));
  return std::min(45.0, -std::log10(rel));
}

void count_row(std::vector<audit_row>& rows, reader& rd, const std::string& statement, const std::string& where,
               const std::string& file, std::size_t paper, bool skipped_when_quick) {
  auto r = row(statement, where, "the same count, exactly");
  if (!rd.ran("dedicated")) rows.push_back(not_computed(r, "not computed in this run (section dedicated)"));
  else if (skipped_when_quick && rd.inputs().quick)
    rows.push_back(not_computed(r, "not computed in this run (section dedicated skips R and P with --quick)"));
  else if (const auto* j = rd.json(file); !j) rows.push_back(not_computed(r, file + " missing"));
  else {
    const auto n = j->at("solutions").size();
    rows.push_back(judge(r, n == paper, std::to_string(n) + " real solutions"));
  }
}

void dedicated_rows(std::vector<audit_row>& rows, reader& rd) {
  const bool ran = rd.ran("dedicated");
  const std::string absent = "not computed in this run (section dedicated)";
  count_row(rows, rd, "Spherical top: the N integrators have 12 real solutions", "4.2, Table 2", "solutions_sphere.json", 12, false);
  {
    auto r = row("Table 3, analytic column: ‖H_R5‖ normalised by N5 (2) (1 to 991.42)", "4.2, Table 3",
                 "every ratio equal to the paper's to its two printed decimals (±0.005)");
    const auto* j = ran ? rd.json("solutions_sphere.json") : nullptr;
    const auto* n5 = j ? find(*j, "N5 ABC (2)") : nullptr;
    if (!n5) rows.push_back(not_computed(r, ran ? "N5 ABC (2) missing" : absent));
    else {
      int within = 0;
      double worst = 0;
      std::string worst_name;
      for (const auto& paper : lv_table3) {
        const std::string name = paper.integrator;
        const double lv = paper.analytic;
        const auto* s = find(*j, name);
        if (!s) continue;
        const double d = s->at("analytic_remainder").get<double>() / n5->at("analytic_remainder").get<double>() - lv;
        within += std::abs(d) <= 0.005 + 1e-9;
        if (std::abs(d) >= std::abs(worst)) worst = d, worst_name = name;
      }
      rows.push_back(judge(r, within == static_cast<int>(lv_table3.size()),
                           std::to_string(within) + " of " + std::to_string(lv_table3.size()) + " equal; largest difference " +
                               significant_text(worst, 2) + " (" + worst_name + ")"));
    }
  }
  count_row(rows, rd, "Water: the N integrators have 90 real solutions over the six permutations", "4.3", "solutions_water.json", 90, false);

  const auto* water = ran ? rd.json("solutions_water.json") : nullptr;
  {
    auto r = row("Table 4 lists the 15 N integrators of smallest analytic remainder for water", "4.3, Table 4",
                 "rotlie's 15 smallest ‖H_R5‖ are the same 15 integrators");
    if (!water) rows.push_back(not_computed(r, absent));
    else {
      std::vector<std::pair<double, std::string>> all;
      for (const auto& s : water->at("solutions")) all.emplace_back(s.at("analytic_remainder").get<double>(), solution_name(s));
      std::sort(all.begin(), all.end());
      std::string extra, missing;
      std::set<std::string> ours;
      for (std::size_t k = 0; k < std::min<std::size_t>(15, all.size()); ++k) ours.insert(all[k].second);
      for (const auto& [name, v] : lv_table4) {
        if (!ours.count(name)) missing += (missing.empty() ? "" : ", ") + name;
        ours.erase(name);
      }
      for (const auto& n : ours) extra += (extra.empty() ? "" : ", ") + n;
      rows.push_back(judge(r, missing.empty() && extra.empty(),
                           missing.empty() && extra.empty() ? "the same 15"
                                                            : "not in rotlie's 15: " + (missing.empty() ? "none" : missing) +
                                                                  "; in rotlie's 15 only: " + (extra.empty() ? "none" : extra)));
    }
  }
  {
    auto r = row("Table 4: analytic remainders from 1.06e-2 (N2 BAC (2)) to 3.83e-2 (N1 ABC (2))", "4.3, Table 4",
                 "every value equal to the paper's to its printed digits (±0.005e-2)");
    if (!water) rows.push_back(not_computed(r, absent));
    else {
      int within = 0;
      double worst = 0;
      std::string worst_name;
      for (const auto& [name, lv] : lv_table4) {
        const auto* s = find(*water, name);
        if (!s) continue;
        const double d = 100 * s->at("analytic_remainder").get<double>() - lv;
        within += std::abs(d) <= 0.005 + 1e-9;
        if (std::abs(d) >= std::abs(worst)) worst = d, worst_name = name;
      }
      rows.push_back(judge(r, within == static_cast<int>(lv_table4.size()),
                           std::to_string(within) + " of 15 equal; largest difference " + significant_text(worst, 2) + "e-2 (" + worst_name + ")"));
    }
  }
  {
    auto r = row("Water: the smallest analytic remainders are N2 BAC (2), then N2 ACB (1)", "4.3, Table 4",
                 "rotlie's first two by ‖H_R5‖");
    if (!water) rows.push_back(not_computed(r, absent));
    else {
      std::vector<std::pair<double, std::string>> all;
      for (const auto& s : water->at("solutions")) all.emplace_back(s.at("analytic_remainder").get<double>(), solution_name(s));
      std::sort(all.begin(), all.end());
      const bool ok = all.size() >= 2 && all[0].second == "N2 BAC (2)" && all[1].second == "N2 ACB (1)";
      rows.push_back(judge(r, ok, all[0].second + " (" + significant_text(100 * all[0].first, 3) + "e-2), " + all[1].second + " (" +
                                      significant_text(100 * all[1].first, 3) + "e-2)"));
    }
  }
  // Coefficients printed in eqs. (74) and (76) (quoted), against the solver's 40-digit values.
  struct printed {
    std::string file, name, coefficient, paper;
  };
  const std::vector<printed> eqs = {
      {"solutions_water.json", "N2 BAC (2)", "a1", "4.5504624774591050429019276281136041301731e-2"},   // LV eq. (74)
      {"solutions_water.json", "N2 BAC (2)", "a2", "1.5208328361334726621353294430175796767150e-1"},   // LV eq. (74)
      {"solutions_water_P.json", "P1 BAC (5)", "a1", "2.6576137190217391781483465189759344419197e-2"},  // LV eq. (76)
      {"solutions_water_P.json", "P1 BAC (5)", "b1", "2.8352180398306075206301328654179005782548e-1"},  // LV eq. (76)
      {"solutions_water_P.json", "P1 BAC (5)", "a2", "2.7103966011355754480520833151108230977015e-1"}}; // LV eq. (76)
  for (const auto* which : {"N2 BAC (2)", "P1 BAC (5)"}) {
    const bool p = std::string(which)[0] == 'P';
    auto r = row(std::string("The coefficients of ") + which + " printed with 41 digits", p ? "4.3, eq. (76)" : "4.3, eq. (74)",
                 "each agrees with rotlie's 40-digit certified value to ≥ 38 significant digits");
    const std::string file = p ? "solutions_water_P.json" : "solutions_water.json";
    const auto* j = ran && !(p && rd.inputs().quick) ? rd.json(file) : nullptr;
    const auto* s = j ? find(*j, which) : nullptr;
    if (!s) {
      rows.push_back(not_computed(r, !ran ? absent : p && rd.inputs().quick ? "not computed in this run (section dedicated skips P with --quick)"
                                                                            : std::string(which) + " missing in " + file));
      continue;
    }
    double least = 45;
    std::string v, lacking;
    for (const auto& e : eqs)
      if (e.name == which && !(s->contains("coefficients") && s->at("coefficients").contains(e.coefficient))) lacking = e.coefficient;
    if (!lacking.empty()) {
      rows.push_back(not_computed(r, std::string(which) + " has no " + lacking + " in " + file));
      continue;
    }
    for (const auto& e : eqs)
      if (e.name == which) {
        const double d = agreeing_digits(s->at("coefficients").at(e.coefficient).get<std::string>(), e.paper);
        least = std::min(least, d);
        v += (v.empty() ? "" : ", ") + e.coefficient + ": " + fixed_text(d, 1);
      }
    rows.push_back(judge(r, least >= 38, "agreeing digits " + v));
  }
  {
    auto r = row("Water: all the coefficients of N2 BAC (2) are positive",
                 "4.3, after eq. (74)", "every stage coefficient > 0 (the second half cites Sheng 1989, Suzuki 1991: not checked)");
    const auto* s = water ? find(*water, "N2 BAC (2)") : nullptr;
    if (!s) rows.push_back(not_computed(r, absent));
    else {
      bool positive = true;
      std::string v;
      for (const auto& [k, text] : s->at("coefficients").items()) {
        const bool p = cln::plusp(decimal(text.get<std::string>()));
        positive = positive && p;
        v += (v.empty() ? "" : ", ") + k + (p ? " > 0" : " ≤ 0");
      }
      rows.push_back(judge(r, positive, v));
    }
  }
  {
    auto r = row("All-positive coefficients are impossible for a classical 4th-order splitting (Sheng 1989; Suzuki 1991)",
                 "4.3, after eq. (74)", "—");
    r.verdict = audit_verdict::cannot_check;
    r.why = "a theorem the paper cites, not a number of rotlie's";
    r.value = "—";
    rows.push_back(r);
  }
  {
    auto r = row("Table 4's analytic remainders are very close, so the best N for water has to be chosen numerically", "4.3, Table 4, Fig. 3",
                 "the analytic order of Table 4's 15 N differs from the numeric order at the top (the favourites differ)");
    const auto* d = rd.ran("accuracy") ? rd.chart("fig3_water") : nullptr;
    if (!water || !d) rows.push_back(not_computed(r, !water ? absent : "not computed in this run (section accuracy)"));
    else {
      std::vector<double> analytic, numeric;
      std::string analytic_best, numeric_best;
      double a_min = 1e300, n_min = 1e300;
      for (const auto& [name, lv] : lv_table4) {
        const auto* s = find(*water, name);
        const auto* c = series(*d, name);
        if (!s || !c) continue;
        analytic.push_back(s->at("analytic_remainder").get<double>());
        numeric.push_back(fit(*c, 4).constant);
        if (analytic.back() < a_min) a_min = analytic.back(), analytic_best = name;
        if (numeric.back() < n_min) n_min = numeric.back(), numeric_best = name;
      }
      rows.push_back(judge(r, analytic_best != numeric_best,
                           "analytic favourite " + analytic_best + ", numeric best " + numeric_best + "; Spearman ρ (analytic, numeric) = " +
                               fixed_text(rank_correlation(analytic, numeric), 3) + " over " + std::to_string(analytic.size())));
    }
  }
  count_row(rows, rd, "Water: the integrator R has 46 real solutions over the six permutations", "4.3", "solutions_water_R.json", 46, true);
  count_row(rows, rd, "Water: the fifteen integrators P have 724 real solutions in total", "4.3", "solutions_water_P.json", 724, true);
}

// ---------------------------------------------------------------- maps (LV 5.2-5.3)

struct map_body {
  double I1 = 0, I2 = 0;
  std::optional<double> ratio;
  bool singular = false;
  std::string best;
  int i = 0, j = 0;
};

struct map_file {
  int K = 0;
  std::vector<map_body> bodies;
};

double fraction_value(const std::string& f) {
  const auto slash = f.find('/');
  return slash == std::string::npos ? std::stod(f) : std::stod(f.substr(0, slash)) / std::stod(f.substr(slash + 1));
}

std::optional<map_file> read_map_file(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::string line;
  map_file m;
  if (!std::getline(in, line)) return std::nullopt;
  const auto header = nlohmann::json::parse(line, nullptr, false);
  if (header.is_discarded() || !header.contains("grid")) throw std::runtime_error(printable_path(file) + " has no map header");
  m.K = header["grid"].get<int>();
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("I") || j.contains("failed")) continue;
    map_body b;
    b.I1 = fraction_value(j["I"][0].get<std::string>());
    b.I2 = fraction_value(j["I"][1].get<std::string>());
    b.i = static_cast<int>(std::lround(fraction_value(j.value("s", "0")) * m.K));
    b.j = static_cast<int>(std::lround(fraction_value(j.value("t", "0")) * m.K));
    if (j.contains("ratio") && j["ratio"].is_number()) b.ratio = j["ratio"].get<double>();
    b.singular = j.contains("singular") && !j["singular"].empty();
    if (j.contains("best") && j["best"].is_string()) b.best = j["best"].get<std::string>();
    m.bodies.push_back(b);
  }
  return m;
}

// Distance to the symmetric tops, as the maps section measures it: min(I2 − I1, 1 − I2) ≤ 1/3.
double asymmetry(const map_body& b) { return std::min(b.I2 - b.I1, 1 - b.I2); }

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

struct bands {
  int n[3] = {0, 0, 0}, wins[3] = {0, 0, 0};
  std::vector<double> log_ratio[3];
  int total = 0, total_wins = 0;
};

bands band_counts(const map_file& m) {
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

std::string share(int a, int n) { return (n ? fixed_text(100.0 * a / n, 1) : std::string("0")) + " % (" + std::to_string(a) + "/" + std::to_string(n) + ")"; }

void maps_rows(std::vector<audit_row>& rows, reader& rd) {
  const auto& in = rd.inputs();
  std::map<std::string, std::optional<map_file>> maps;
  for (const std::string f : {"N", "P"}) {
    const fs::path given = in.maps_folder.empty() ? fs::path() : in.maps_folder / ("map-" + f + ".jsonl");
    if (!rd.ran("maps")) maps[f] = std::nullopt;
    else if (!given.empty() && fs::exists(given)) maps[f] = read_map_file(given);
    else maps[f] = read_map_file(in.folder / ("map-" + f + ".jsonl"));
  }
  const auto absent = [&](const std::string& f) {
    return rd.ran("maps") ? "map-" + f + ".jsonl missing" : std::string("not computed in this run (section maps)");
  };
  const auto grid = [](const map_file& m) { return " (--grid " + std::to_string(m.K) + ", " + std::to_string(m.bodies.size()) + " bodies)"; };
  {
    auto r = row("N beats RS4 S5 McLachlan (best permutations, × (12/9)^4) only for some bodies of the triangle", "5.2, Fig. 8",
                 "a fraction of the bodies with ratio > 1 strictly between 0 and 50 %");
    if (!maps["N"]) rows.push_back(not_computed(r, absent("N")));
    else {
      const auto b = band_counts(*maps["N"]);
      const double f = b.total ? static_cast<double>(b.total_wins) / b.total : 0;
      std::string where;
      int listed = 0;
      for (const auto& x : maps["N"]->bodies)
        if (x.ratio && *x.ratio > 1 && listed++ < 5)
          where += (where.empty() ? "" : ", ") + std::string("(") + significant_text(x.I1, 3) + ", " + significant_text(x.I2, 3) + "; δ " + significant_text(asymmetry(x), 2) +
                   "; " + x.best + ")";
      rows.push_back(judge(r, b.total_wins > 0 && f < 0.5,
                           "N better at " + share(b.total_wins, b.total) + (where.empty() ? "" : ": (I1, I2) = " + where) + grid(*maps["N"])));
    }
  }
  {
    auto r = row("RS4 S5 McLachlan is especially more accurate than N near the symmetric tops", "5.2, Fig. 8",
                 "median log10 ratio lower for δ < 1/9 than for δ ≥ 2/9 (δ = distance to the tops); the wins' shares are shown");
    if (!maps["N"]) rows.push_back(not_computed(r, absent("N")));
    else {
      const auto b = band_counts(*maps["N"]);
      const double near = median(b.log_ratio[0]), far = median(b.log_ratio[2]);
      const bool ok = b.n[0] > 0 && b.n[2] > 0 && near < far;
      rows.push_back(judge(r, ok, "median log10 ratio " + fixed_text(near, 2) + " near the tops, " + fixed_text(median(b.log_ratio[1]), 2) +
                                      " in between, " + fixed_text(far, 2) + " very asymmetric; N wins " + share(b.wins[0], b.n[0]) +
                                      " near, " + share(b.wins[2], b.n[2]) + " far" + grid(*maps["N"])));
    }
  }
  {
    auto r = row("P beats RS4 S5 McLachlan (× (12/11)^4) only for very asymmetric bodies", "5.3, Fig. 10",
                 "P wins somewhere, never near the tops (δ < 1/9)");
    if (!maps["P"]) rows.push_back(not_computed(r, absent("P")));
    else {
      const auto b = band_counts(*maps["P"]);
      rows.push_back(judge(r, b.total_wins > 0 && b.wins[0] == 0,
                           "P wins " + share(b.wins[0], b.n[0]) + " near the tops, " + share(b.wins[1], b.n[1]) + " in between, " +
                               share(b.wins[2], b.n[2]) + " very asymmetric; median log10 ratio " + fixed_text(median(b.log_ratio[0]), 2) +
                               ", " + fixed_text(median(b.log_ratio[1]), 2) + ", " + fixed_text(median(b.log_ratio[2]), 2) + grid(*maps["P"])));
    }
  }
  {
    auto r = row("The P map (Fig. 9) has isolated points where a singularity occurs in the automatic resolution", "5.3, Fig. 9",
                 "singular bodies exist and none has a singular neighbour on the grid (their positions in the paper cannot be read)");
    if (!maps["P"]) rows.push_back(not_computed(r, absent("P")));
    else {
      std::set<std::pair<int, int>> singular;
      std::string v;
      for (const auto& x : maps["P"]->bodies)
        if (x.singular) {
          singular.insert({x.i, x.j});
          v += (v.empty() ? "" : ", ") + std::string("(") + significant_text(x.I1, 3) + ", " + significant_text(x.I2, 3) + ")";
        }
      bool isolated = true;
      for (const auto& [i, j] : singular)
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            if ((di || dj) && singular.count({i + di, j + dj})) isolated = false;
      rows.push_back(judge(r, !singular.empty() && isolated,
                           std::to_string(singular.size()) + " singular bod" + (singular.size() == 1 ? "y" : "ies") +
                               (v.empty() ? "" : " at (I1, I2) = " + v) + grid(*maps["P"])));
    }
  }
}

// ---------------------------------------------------------------- measured map ratios

void truth_rows(std::vector<audit_row>& rows, reader& rd) {
  const auto& in = rd.inputs();
  const std::string file = "maps-truth/measured-ratios.csv";
  std::optional<csv_table> t;
  if (rd.ran("maps-truth")) t = read_csv(in.folder / file);
  for (const std::string f : {"N", "P"}) {
    auto corr = row("The analytic remainder predicts the measured gain of the best " + f + " over RS4 S5 McLachlan (section 5 relies on it)",
                    "5 (from 4.2)", "Spearman rank correlation of analytic and measured (equal h/C) ratios ≥ 0.8");
    auto flips = row("The analytic verdict \"" + f + " better than RS4 S5 McLachlan\" is the measured one", "5.2-5.3, Figs. 8, 10",
                     "the verdict (ratio > 1) flips at ≤ 10 % of the measured bodies");
    if (!t) {
      const std::string why = rd.ran("maps-truth") ? file + " missing" : "not computed in this run (section maps-truth)";
      rows.push_back(not_computed(corr, why));
      rows.push_back(not_computed(flips, why));
      continue;
    }
    const auto fam = t->column("family"), a = t->column("analytic_ratio"), m = t->column("measured_ratio_h");
    if (!fam || !a || !m) throw std::runtime_error(file + " lacks family, analytic_ratio or measured_ratio_h");
    std::vector<double> x, y;
    int flipped = 0;
    for (const auto& rw : t->rows) {
      if (rw[*fam] != f) continue;
      double ar = 0, mr = 0;
      try {
        ar = std::stod(rw[*a]), mr = std::stod(rw[*m]);
      } catch (const std::exception&) {
        continue;
      }
      if (!std::isfinite(ar) || !std::isfinite(mr)) continue;
      x.push_back(ar), y.push_back(mr);
      flipped += (ar > 1) != (mr > 1);
    }
    if (x.size() < 3) {
      rows.push_back(not_computed(corr, "fewer than 3 measured " + f + " bodies in " + file));
      rows.push_back(not_computed(flips, "fewer than 3 measured " + f + " bodies in " + file));
      continue;
    }
    const double rho = rank_correlation(x, y);
    rows.push_back(judge(corr, rho >= 0.8, "Spearman ρ = " + fixed_text(rho, 3) + " over " + std::to_string(x.size()) + " bodies"));
    rows.push_back(judge(flips, flipped <= 0.1 * static_cast<double>(x.size()),
                         "flips at " + share(flipped, static_cast<int>(x.size()))));
  }
}

std::string csv_field(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = (static_cast<double>(i + j) / 2) + 1;
    i = j + 1;
  }
  return r;
}

}  // namespace

double rank_correlation(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 3) return std::nan("");
  const auto rx = ranks(x), ry = ranks(y);
  const double n = static_cast<double>(x.size()), mean = (n + 1) / 2;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < rx.size(); ++i) {
    sxy += (rx[i] - mean) * (ry[i] - mean);
    sxx += (rx[i] - mean) * (rx[i] - mean);
    syy += (ry[i] - mean) * (ry[i] - mean);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : std::nan("");
}

std::vector<audit_row> audit_rows_from_reports(const audit_inputs& in) {
  reader rd(in);
  std::vector<audit_row> rows;
  dedicated_rows(rows, rd);
  accuracy_rows(rows, rd);
  maps_rows(rows, rd);
  truth_rows(rows, rd);
  return rows;
}

std::string verdict_text(const audit_row& row) {
  switch (row.verdict) {
    case audit_verdict::holds: return "holds";
    case audit_verdict::does_not_hold: return "does not hold";
    case audit_verdict::cannot_check: return "cannot be checked: " + row.why;
    case audit_verdict::not_computed: return row.why.rfind("not computed", 0) == 0 ? row.why : "not computed in this run: " + row.why;
  }
  return "";
}

std::string audit_csv(const std::vector<audit_row>& rows) {
  std::string out = "statement,section,rotlie_value,tolerance,verdict\n";
  for (const auto& r : rows)
    out += csv_field(r.statement) + "," + csv_field(r.where) + "," + csv_field(r.value) + "," + csv_field(r.tolerance) + "," +
           csv_field(verdict_text(r)) + "\n";
  return out;
}

nlohmann::json audit_json(const std::vector<audit_row>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& r : rows) {
    const char* key = r.verdict == audit_verdict::holds           ? "holds"
                      : r.verdict == audit_verdict::does_not_hold ? "does_not_hold"
                      : r.verdict == audit_verdict::cannot_check  ? "cannot_check"
                                                                  : "not_computed";
    a.push_back({{"statement", r.statement}, {"section", r.where}, {"rotlie_value", r.value}, {"tolerance", r.tolerance},
                 {"verdict", key}, {"verdict_text", verdict_text(r)}});
  }
  return {{"source", "Laskar & Vaillant (2018), sections 4 and 5"}, {"rows", a}};
}

}  // namespace rotlie::reports
