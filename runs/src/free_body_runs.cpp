#include "rotlie/runs/free_body_runs.hpp"

#include <boost/multiprecision/float128.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/free_body_observers.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/runs/number_text.hpp"

namespace rotlie::runs {
namespace {

constexpr long max_steps = 100'000'000;

// The exact flow's time limit is a property of the arguments: bad input, not a failure.
template <class T>
void check_time_limit(const models::exact_free_body<T>& exact, double total) {
  if (total > static_cast<double>(exact.max_time()))
    throw bad_input("--T = " + significant_text(total) + " is beyond the exact flow's limit of " +
                    significant_text(static_cast<double>(exact.max_time())) + " for this body and G0 (|ω| T ≤ 2^60 rad)");
}

template <class T>
models::body_state<T> initial_state(const models::vec3<double>& g0) {
  return {models::mat3<T>::identity(), {T(g0[0]), T(g0[1]), T(g0[2])}};
}

// The protocol in scalar T, fitted over the finest points (at most four) above T's round-off floor
// and well above the exact reference's estimated error.
template <class T>
models::order_measurement order_in(const free_body_input& in, const models::vec3<double>& g0, double total, int first,
                                   int last) {
  const auto initial = initial_state<T>(g0);
  const auto method = models::free_body_method(in.table, models::moments_from_text<T>(in.inertia));
  check_time_limit(models::exact_free_body<T>(method.system().moments(), initial), total);
  models::fit_rule rule;
  rule.at_most = 4;
  rule.floor = models::round_off_floor<T>();
  return models::measure_order(method, initial, T(total), first, last, rule);
}

}  // namespace

free_body_input free_body_of(const std::string& scheme, const std::string& inertia, foreign_table policy,
                             const warning_sink& warn) {
  const auto body = numeric_body(inertia);
  return {scheme_named(scheme, body, policy, warn), lie::inertia_text(body)};
}

long step_count(double total, double h) {
  const double n = total / h;
  if (n > static_cast<double>(max_steps))
    throw bad_input("T/h = " + std::to_string(n) + " steps is over the limit of " + std::to_string(max_steps));
  const long steps = std::lround(n);
  if (steps < 1 || std::abs(static_cast<double>(steps) * h - total) > 1e-9 * total)
    throw bad_input("--T must be a whole number of steps --h (T/h = " + std::to_string(n) + ")");
  return steps;
}

integrate_result integrate_run(const free_body_input& in, const models::vec3<double>& G0, double h, double T,
                               const std::function<void(long, long)>& progress) {
  integrate_result r;
  r.scheme = in.table.name;
  r.h = h;
  r.T = T;
  r.steps = step_count(T, h);
  const auto initial = initial_state<double>(G0);
  const auto method = models::free_body_method(in.table, models::moments_from_text<double>(in.inertia));
  r.cost = method.cost();
  const models::exact_free_body<double> exact(method.system().moments(), initial);
  check_time_limit(exact, T);
  auto guard = models::stop_unless_finite<double>();
  models::flow_attitude_error<double> attitude(exact);
  auto show_progress = [&](long k, double, const models::body_state<double>&) {
    if (progress && k % 1000000 == 0) progress(k, r.steps);
  };
  auto s = initial;
  models::integrate(method, s, h, r.steps, guard, attitude, show_progress);
  if (guard.stopped())
    throw std::runtime_error("the integration diverged (NaN): the step is beyond the scheme's stability limit");
  r.point = {h, h / method.cost(), attitude.mean(), attitude.reference_mean()};
  r.cpu_s = models::cpu_seconds_per_unit_time(method, initial, h) * T;
  return r;
}

order_result order_run(const free_body_input& in, const models::vec3<double>& G0, double T, int first, int last,
                       const std::string& scalar) {
  order_result r;
  r.scheme = in.table.name;
  r.scalar = scalar;
  r.declared_order = in.table.order;
  if (scalar == "double")
    r.measurement = order_in<double>(in, G0, T, first, last);
  else if (scalar == "long-double")
    r.measurement = order_in<long double>(in, G0, T, first, last);
  else if (scalar == "float128")
    r.measurement = order_in<boost::multiprecision::float128>(in, G0, T, first, last);
  else
    throw bad_input("--scalar must be double, long-double or float128, got '" + scalar + "'");
  // CPU per run in double (the scalar a user integrates with), stepping only
  const auto timing = models::free_body_method(in.table, models::moments_from_text<double>(in.inertia));
  const auto initial = initial_state<double>(G0);
  for (const auto& p : r.measurement.points) r.cpu_s.push_back(models::cpu_seconds_per_unit_time(timing, initial, p.h, 0.005) * T);
  return r;
}

exact_result exact_run(const lie::moments_of_inertia& body, const models::vec3<double>& G0, double T) {
  const auto I = models::moments_from_text<double>(lie::inertia_text(body));
  const models::exact_free_body<double> exact(I, initial_state<double>(G0));
  check_time_limit(exact, T);
  const auto e = exact.evaluate(T);
  return {T, e.state, static_cast<double>(e.error_estimate)};
}

double cpu_seconds_per_step(const schemes::scheme_table& table, const models::vec3<double>& I, const step_timing& how) {
  const auto method = models::free_body_method(table, I);
  models::body_state<double> s;
  s.G = {1, 1, 1};
  constexpr double h = 1.0 / 64;
  double best = std::numeric_limits<double>::infinity();
  for (int repeat = 0; repeat < how.repeats; ++repeat)
    best = std::min(best, models::cpu_seconds_per_unit_time(method, s, h, how.min_seconds) * h);
  return best;
}

}  // namespace rotlie::runs
