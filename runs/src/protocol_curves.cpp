#include "rotlie/runs/protocol_curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {
namespace {

constexpr int fit_points = 3;

template <class T>
models::body_state<T> paper_initial_state() {
  models::body_state<T> s;
  s.G = {1, 1, 1};  // LV section 4.1
  return s;
}

}  // namespace

protocol_runner::protocol_runner(const lie::moments_of_inertia& body, int min_level, int max_level, bool time_steps)
    : inertia_(lie::inertia_text(body)), I_(models::moments_from_text<long double>(inertia_)),
      initial_(paper_initial_state<long double>()), exact_(I_, initial_, 1.0L, max_level),
      min_level_(min_level), max_level_(max_level), time_steps_(time_steps) {
  if (min_level < 0 || max_level - min_level + 1 < fit_points)
    throw std::invalid_argument("the protocol needs at least three step levels");
}

scheme_curve protocol_runner::run(const schemes::scheme_table& table) const {
  const auto method = models::free_body_method(table, I_);
  scheme_curve c;
  c.name = table.name;
  c.cost = method.cost();
  c.order = table.order;
  const auto fast = models::free_body_method(table, models::moments_from_text<double>(inertia_));
  const auto s0 = paper_initial_state<double>();
  // The fastest of several short timings: interference from the rest of the machine only ever
  // slows a run down, and errors at equal CPU time go as the 4th power of this number.
  const double h_timing = 1.0 / 64;
  c.seconds_per_step = time_steps_ ? std::numeric_limits<double>::infinity() : 0;
  for (int repeat = 0; time_steps_ && repeat < 7; ++repeat)
    c.seconds_per_step =
        std::min(c.seconds_per_step, models::cpu_seconds_per_unit_time(fast, s0, h_timing, 0.005) * h_timing);
  std::vector<models::protocol_point> measured;
  for (int level = min_level_; level <= max_level_; ++level) {
    curve_point p;
    p.h = std::ldexp(1.0, -level);
    p.h_over_cost = p.h / c.cost;
    const auto r = models::sampled_run(method, initial_, exact_, level);
    p.error = static_cast<double>(r.error);
    p.cpu_seconds = c.seconds_per_step / p.h;
    c.points.push_back(p);
    measured.push_back({p.h, p.h_over_cost, p.error, static_cast<double>(r.reference_error)});
  }
  // The three finest points, every one of them (long double's reference is far below the errors).
  models::fit_rule rule;
  rule.finest = fit_points;
  rule.margin = 0;
  c.slope = models::fitted_order(measured, rule);
  double sum = 0;
  for (std::size_t i = c.points.size() - fit_points; i < c.points.size(); ++i)
    sum += c.points[i].error / std::pow(c.points[i].h_over_cost, c.order);
  c.constant = sum / fit_points;
  return c;
}

scheme_curve protocol_runner::best_permutation(const std::string& base_name) const {
  scheme_curve best;
  best.constant = std::numeric_limits<double>::infinity();
  for (const auto& perm : bch::permutation_names()) {
    const auto table = schemes::reference_scheme(base_name + ":" + perm);
    if (!table) throw std::invalid_argument("unknown reference scheme " + base_name);
    auto c = run(*table);
    if (c.constant < best.constant) best = std::move(c);
  }
  return best;
}

double ratio_at_equal_reduced_step(const scheme_curve& worse, const scheme_curve& better) {
  if (worse.order != better.order) throw std::invalid_argument("ratios compare schemes of the same order");
  return worse.constant / better.constant;
}

double ratio_at_equal_cpu_time(const scheme_curve& worse, const scheme_curve& better) {
  // error = constant (h/C)^p and cpu per unit time = t_step / h, so at equal cpu the error is
  // constant (t_step / C)^p / cpu^p.
  const int p = worse.order;
  return ratio_at_equal_reduced_step(worse, better) *
         std::pow((worse.seconds_per_step / worse.cost) / (better.seconds_per_step / better.cost), p);
}

const solver::dedicated_solution& find_solution(const solver::family_result& r, const std::string& scheme,
                                                const std::string& perm, int label) {
  for (const auto& s : r.solutions)
    if (s.scheme == scheme && s.permutation == perm && s.label == label) return s;
  throw std::runtime_error("the solver found no " + scheme + " " + perm + " (" + std::to_string(label) + ")");
}

finest_fit fit_finest(std::vector<std::pair<double, double>> points, int order) {
  std::sort(points.begin(), points.end());
  if (points.size() < static_cast<std::size_t>(fit_points)) throw std::runtime_error("a curve of fewer than three points");
  points.resize(fit_points);
  finest_fit f;
  std::vector<models::protocol_point> measured;  // coarse to fine, as the fit takes them
  for (auto p = points.rbegin(); p != points.rend(); ++p) measured.push_back({p->first, p->first, p->second, 0});
  for (const auto& [x, y] : points) f.constant += y / std::pow(x, order) / fit_points;
  models::fit_rule rule;
  rule.margin = 0;
  f.slope = models::fitted_order(measured, rule);
  return f;
}

}  // namespace rotlie::runs
