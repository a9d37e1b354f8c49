#include "rotlie/reports/protocol_curves.hpp"

#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::reports {
namespace {

constexpr int fit_points = 3;

models::vec3<long double> moments(const lie::moments_of_inertia& body) {
  models::vec3<long double> I{};
  for (std::size_t k = 0; k < 3; ++k)  // exact rational → long double, one rounding per part
    I[k] = static_cast<long double>(cln::double_approx(cln::numerator(body.I[k]))) /
           static_cast<long double>(cln::double_approx(cln::denominator(body.I[k])));
  return I;
}

models::body_state<long double> paper_initial_state() {
  models::body_state<long double> s;
  s.G = {1, 1, 1};  // LV section 4.1
  return s;
}

}  // namespace

protocol_runner::protocol_runner(const lie::moments_of_inertia& body, int min_level, int max_level, bool time_steps)
    : I_(moments(body)), initial_(paper_initial_state()), exact_(I_, initial_, 1.0L, max_level),
      min_level_(min_level), max_level_(max_level), time_steps_(time_steps) {
  if (min_level < 0 || max_level - min_level + 1 < fit_points)
    throw std::invalid_argument("the protocol needs at least three step levels");
}

scheme_curve protocol_runner::run(const schemes::scheme_table& table) const {
  const models::composition_stepper<long double> stepper(table, I_);
  scheme_curve c;
  c.name = table.name;
  c.cost = stepper.cost();
  c.order = table.order;
  const models::vec3<double> I{static_cast<double>(I_[0]), static_cast<double>(I_[1]), static_cast<double>(I_[2])};
  const models::composition_stepper<double> fast(table, I);
  models::body_state<double> s0;
  s0.G = {1, 1, 1};
  // The fastest of several short timings: interference from the rest of the machine only ever
  // slows a run down, and errors at equal CPU time go as the 4th power of this number.
  const double h_timing = 1.0 / 64;
  c.seconds_per_step = time_steps_ ? std::numeric_limits<double>::infinity() : 0;
  for (int repeat = 0; time_steps_ && repeat < 7; ++repeat)
    c.seconds_per_step =
        std::min(c.seconds_per_step, models::cpu_seconds_per_unit_time(fast, s0, h_timing, 0.005) * h_timing);
  std::vector<double> hs, es;
  for (int level = min_level_; level <= max_level_; ++level) {
    curve_point p;
    p.h = std::ldexp(1.0, -level);
    p.h_over_cost = p.h / c.cost;
    p.error = static_cast<double>(models::mean_attitude_error(stepper, initial_, exact_, level));
    p.cpu_seconds = c.seconds_per_step / p.h;
    c.points.push_back(p);
  }
  double sum = 0;
  for (std::size_t i = c.points.size() - fit_points; i < c.points.size(); ++i) {
    hs.push_back(c.points[i].h);
    es.push_back(c.points[i].error);
    sum += c.points[i].error / std::pow(c.points[i].h_over_cost, c.order);
  }
  c.slope = models::fitted_slope(hs, es);
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

}  // namespace rotlie::reports
