#pragma once
// The paper's numeric protocol (LV section 4.1): from G0 with the identity attitude, integrate to
// T with step h and average, over every step, the R^9 distance between the attitude and the exact
// one (exact_samples: the exact solution sampled once on the finest grid, with its own error
// estimate). Every run is models::integrate on the composition engine with the observers of
// free_body_observers.hpp; the order is fitted by the one rule of order_fit.hpp.
#include <stdexcept>
#include <vector>

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/exact_samples.hpp"
#include "rotlie/models/free_body_observers.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/order_fit.hpp"

namespace rotlie::models {

/// Mean attitude error of a run with 2^level steps of size T/2^level, and the reference's share.
template <class T>
struct sampled_error {
  T error{}, reference_error{};
};

template <class T>
sampled_error<T> sampled_run(const free_body_composition<T>& method, const body_state<T>& initial,
                             const exact_samples<T>& exact, int level) {
  sampled_attitude_error<T> error(exact, level);
  const long n = 1L << level;
  body_state<T> s = initial;
  integrate(method, s, exact.total_time() / static_cast<T>(n), n, error);
  return {error.mean(), error.reference_mean()};
}

/// The mean attitude error alone.
template <class T>
T mean_attitude_error(const free_body_composition<T>& method, const body_state<T>& initial, const exact_samples<T>& exact,
                      int level) {
  return sampled_run(method, initial, exact, level).error;
}

/// CPU seconds per unit of simulated time for step h, measured on repeated runs of at least
/// `minimum_seconds` of this thread's CPU time (stepping only, no observer; CPU, not wall time, so
/// that the figure does not depend on the machine's load).
template <class T>
double cpu_seconds_per_unit_time(const free_body_composition<T>& method, const body_state<T>& initial, const T& h,
                                 double minimum_seconds = 0.02) {
  constexpr long chunk = 256;
  long steps = 0;
  const double start = thread_cpu_seconds();
  double elapsed = 0;
  body_state<T> s = initial;
  do {
    steps += integrate(method, s, h, chunk);
    elapsed = thread_cpu_seconds() - start;
  } while (elapsed < minimum_seconds);
  volatile double sink = static_cast<double>(s.G[0]);
  (void)sink;
  return elapsed / (static_cast<double>(steps) * static_cast<double>(h));
}

struct order_measurement {
  std::vector<protocol_point> points;  ///< one per level, coarse to fine
  double slope = 0;                    ///< fitted over the points the rule selects (NaN if < 2)
};

/// Errors at h = T/2^level for level = first … last, and the order fitted by `rule`.
template <class T>
order_measurement measure_order(const free_body_composition<T>& method, const body_state<T>& initial,
                                const T& total_time, int first, int last, const fit_rule& rule) {
  if (first < 0 || last < first || last > 20) throw std::invalid_argument("step levels must satisfy 0 ≤ first ≤ last ≤ 20");
  const exact_samples<T> exact(method.system().moments(), initial, total_time, last);
  order_measurement m;
  for (int level = first; level <= last; ++level) {
    const double h = static_cast<double>(total_time) / static_cast<double>(1L << level);
    const auto r = sampled_run(method, initial, exact, level);
    m.points.push_back({h, h / method.cost(), static_cast<double>(r.error), static_cast<double>(r.reference_error)});
  }
  m.slope = fitted_order(m.points, rule);
  return m;
}

/// The same for a table on a body, fitted over the finest `fit_points` points that the scheme's
/// error (not the reference's) dominates.
template <class T>
order_measurement measure_order(const schemes::scheme_table& table, const vec3<T>& I, const body_state<T>& initial,
                                const T& total_time, int first, int last, int fit_points) {
  fit_rule rule;
  rule.finest = static_cast<std::size_t>(std::max(fit_points, 0));
  return measure_order(free_body_method(table, I), initial, total_time, first, last, rule);
}

}  // namespace rotlie::models
