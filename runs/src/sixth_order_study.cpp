// The measurements of the report's section "Beyond the paper" (see sixth_order_study.hpp). By default the
// search covers the systems of the words listed in `searched_systems` (the best ones of the broad scan);
// `full` scans every 21-stage palindrome.
#include "rotlie/runs/sixth_order_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/quad.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {

namespace {

// The systems the default search covers: the best (word, permutation) systems by ‖H_R7‖ of the broad
// scan (`rotlie sixth --inertia water --all --starts 40`: 3 066 systems, 892 s of CPU) and of its
// continuation to 400 starts on its ten best systems, so that the default finds their roots again with
// the same start sequence; the last one is the first scheme certified. `full` repeats the broad scan.
const std::vector<std::pair<std::string, std::string>> searched_systems = {
    {"ABABACBACBCBCABCABABA", "CAB"}, {"ABACBCBCACACACBCBCABA", "ABC"}, {"ABACACABCABACBACACABA", "ACB"},
    {"ABABABACABCBACABABABA", "BCA"},
};
// The spherical top: permutation ABC only (every permutation of the sphere is the same body); the best
// systems of `rotlie sixth --inertia sphere --all --starts 20`.
const std::vector<std::string> sphere_words = {"ABCBCABCBACABCBACBCBA", "ABCBACBABCACBABCABCBA"};
constexpr int sphere_starts = 20;
constexpr int digits = sixth_order_digits;
constexpr int min_level = 2, max_level = 8;  // the protocol's h = 2^-i (long double errors, double CPU)

// The CPU time of one step of the double stepper (this thread's CPU time, not wall time: the machine
// may be shared), the fastest of several runs of at least 10 ms at h = 1/64; the curve's CPU column
// follows (t_step / h per unit of simulated time).
void time_steps(scheme_curve& c, const schemes::scheme_table& t, const lie::moments_of_inertia& body) {
  c.seconds_per_step = cpu_seconds_per_step(t, models::moments_from_text<double>(lie::inertia_text(body)), {9, 0.01});
  for (auto& p : c.points) p.cpu_seconds = c.seconds_per_step / p.h;
}

// The fitted slope of the mean attitude error in float128 (G0 = (1, 1, 1), T = 1, h = 1/16 … 1/256).
double quad_slope(const schemes::scheme_table& t, const lie::moments_of_inertia& body) {
  const auto I = models::moments_from_text<quad>(lie::inertia_text(body));
  models::body_state<quad> s0;
  s0.G = {1, 1, 1};
  return models::measure_order<quad>(t, I, s0, quad(1), 4, 8, 5).slope;
}

// ‖H_R7‖ of any palindromic table: its stages mapped onto the layout of its word by position.
double remainder7_of(const schemes::scheme_table& t, const std::string& base_word, const lie::moments_of_inertia& body) {
  const auto layout = bch::layout_scheme(base_word, solver::splitting_of(t.splitting), t.permutation.empty() ? "ABC" : t.permutation);
  std::map<std::string, double> values;
  for (std::size_t i = 0; i < layout.stages.size(); ++i) values[layout.stages[i].coefficient] = std::stod(t.stages[i].value);
  return solver::remainder7_norm(layout, body, values);
}

using progress_sink = std::function<void(const std::string&)>;

void search(sixth_order_study_result& out, bool quick, const lie::moments_of_inertia& water, const progress_sink& progress) {
  const double t0 = models::thread_cpu_seconds();
  solver::scan_rule rule;
  if (out.full) {
    rule.budget = sixth_order_full_starts;
    for (const auto& word : solver::palindromic_words(21, bch::splitting::abc))
      for (const auto& p : bch::permutation_names()) out.systems.push_back({word, p});
  } else {
    rule.budget = quick ? sixth_order_default_starts / 4 : sixth_order_default_starts;
    for (const auto& [word, p] : searched_systems) out.systems.push_back({word, p});
  }
  out.starts = rule.budget;
  std::size_t index = 0;
  for (auto& r : out.systems) {
    if (++index % 50 == 1) progress("searching system " + std::to_string(index) + " of " + std::to_string(out.systems.size()));
    solver::continue_scan(solver::sixth_order_conditions(bch::layout_scheme(r.word, bch::splitting::abc, r.permutation), water),
                          r, rule);
  }
  out.statistics = solver::statistics_of(out.systems);
  out.search_seconds = models::thread_cpu_seconds() - t0;
}

void polish_best(sixth_order_study_result& out, const lie::moments_of_inertia& water, const progress_sink& progress) {
  const auto other = lie::parse_moments("1/2,4/5,1");
  std::map<std::string, int> labels;
  for (const auto& r : solver::rank_roots(out.systems, water, bch::splitting::abc)) {
    if (static_cast<int>(out.found.size()) >= sixth_order_tables_shown) break;
    const auto s = solver::sixth_order_conditions(bch::layout_scheme(r.word, bch::splitting::abc, r.permutation), water);
    std::vector<cln::cl_RA> x;
    try {
      x = solver::polished_root(s, r.x, digits);
    } catch (const std::runtime_error& e) {
      out.skipped.push_back(r.word + ":" + r.permutation + " (" + e.what() + ")");
      continue;
    }
    const int label = ++labels[r.word + ":" + r.permutation];
    const std::string name = "D6:" + r.word + ":" + r.permutation + ":" + std::to_string(label);
    sixth_order_found f;
    f.text = solver::sixth_order_table_text(s, x, digits, water, name,
                                            "rotlie report (Beyond the paper): H_R3 = H_R5 = 0, Newton from random starts, polished");
    f.table = schemes::parse_scheme_table(f.text);
    f.cost = schemes::cost_in_rotations(f.table);
    f.remainder7 = r.remainder7;
    f.residual = cln::double_approx(solver::sixth_order_residual(s, x, digits));
    f.hits = r.hits;
    progress("float128 slopes of " + name);
    f.slope_water = quad_slope(f.table, water);
    f.slope_other = quad_slope(f.table, other);
    f.file = "D6-" + r.word + "-" + r.permutation + "-" + std::to_string(label) + ".table";
    out.found.push_back(std::move(f));
  }
}

// Isolated 6th-order solutions for the spherical top: polished roots with a regular Jacobian.
void sphere_roots(sixth_order_study_result& out, const progress_sink& progress) {
  progress("the spherical top");
  const auto sphere = lie::parse_moments("sphere"), water = lie::parse_moments("water");
  std::vector<solver::scanned_system> systems;
  solver::scan_rule rule;
  rule.budget = sphere_starts;
  for (const auto& word : sphere_words) {
    systems.push_back({word, "ABC"});
    solver::continue_scan(solver::sixth_order_conditions(bch::layout_scheme(word, bch::splitting::abc, "ABC"), sphere),
                          systems.back(), rule);
  }
  for (const auto& r : solver::rank_roots(systems, sphere, bch::splitting::abc)) {
    const auto s = solver::sixth_order_conditions(bch::layout_scheme(r.word, bch::splitting::abc, "ABC"), sphere);
    sixth_order_sphere_root root;
    root.word = r.word;
    root.remainder7 = r.remainder7;
    root.condition = solver::jacobian_condition_ratio(s, r.x);
    try {
      const auto x = solver::polished_root(s, r.x, digits);
      const std::string name = "D6:" + r.word + ":ABC (sphere)";
      const auto table = schemes::parse_scheme_table(solver::sixth_order_table_text(s, x, digits, sphere, name, "rotlie report"));
      root.residual = cln::double_approx(solver::sixth_order_residual(s, x, digits));
      root.slope_sphere = quad_slope(table, sphere);
      root.slope_water = quad_slope(table, water);
      root.polished = true;
    } catch (const std::runtime_error& e) {
      root.failure = e.what();
    }
    out.sphere.push_back(std::move(root));
  }
}

}  // namespace

double cpu_for_error(const scheme_curve& c, double e) {
  return c.seconds_per_step / c.cost / std::pow(e / c.constant, 1.0 / c.order);
}

double error_at_cpu(const scheme_curve& c, double cpu) {
  return c.constant * std::pow(c.seconds_per_step / c.cost / cpu, c.order);
}

sixth_order_study_result sixth_order_study(bool quick, bool full, const progress_sink& progress_to) {
  const auto progress = [&](const std::string& line) {
    if (progress_to) progress_to(line);
  };
  const double t0 = models::thread_cpu_seconds();
  sixth_order_study_result out;
  out.full = full;
  out.remainder_word_limit = bch::max_word_length;
  const auto water = lie::parse_moments("water");
  progress("searching");
  search(out, quick, water, progress);
  polish_best(out, water, progress);
  sphere_roots(out, progress);

  // Curves: the protocol of LV section 4.1 (long double errors, double CPU time per step).
  progress("accuracy curves");
  const protocol_runner runner(water, min_level, max_level, false);
  for (const auto& f : out.found) {
    out.dedicated6.push_back(runner.run(f.table));
    time_steps(out.dedicated6.back(), f.table, water);
  }
  for (const auto& base : schemes::reference_sixth_order_scheme_names()) {
    out.general6.push_back(runner.best_permutation(base));
    time_steps(out.general6.back(), *schemes::reference_scheme(out.general6.back().name), water);
  }
  for (const auto& base : schemes::reference_scheme_names())
    if (schemes::reference_scheme(base)->order == 4) {
      out.fourth.push_back(runner.best_permutation(base));
      time_steps(out.fourth.back(), *schemes::reference_scheme(out.fourth.back().name), water);
    }
  for (const char* name : {"N2:BAC:2", "P1:BAC:5", "R:ABC:4"}) {
    const auto table = scheme_named(name, water);
    auto c = runner.run(table);
    time_steps(c, table, water);
    c.name = name;
    out.fourth.push_back(std::move(c));
  }

  // The general compositions: float128 slope at their best permutation, ‖H_R7‖.
  for (const auto& c : out.general6) {
    const auto t = *schemes::reference_scheme(c.name);
    const auto base = *schemes::reference_scheme(c.name.substr(0, c.name.find(':')));
    sixth_order_general g;
    g.remainder7 = std::nan("");
    try {
      g.remainder7 = remainder7_of(t, base.word, water);
    } catch (const std::exception&) {
    }
    g.quad_slope = quad_slope(t, water);
    out.general.push_back(g);
  }
  out.seconds = models::thread_cpu_seconds() - t0;
  return out;
}

}  // namespace rotlie::runs
