#pragma once
// The paper's numeric protocol (LV section 4.1): from G0 with the identity attitude, integrate to
// T with step h and average, over every step, the R^9 distance between the attitude and the exact
// one. The exact solution is sampled once on the finest grid and reused for every coarser h, with
// its own error estimate (exact_free_body::evaluate), so that no point of an order fit measures the
// reference instead of the scheme.
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"

namespace rotlie::models {

/// A scheme error is attributed to the scheme only when it is this many times the reference's.
inline constexpr double reference_margin = 10;

/// The exact attitude at t_k = k·T/2^finest, k = 0 … 2^finest, and its estimated error.
template <class T>
class exact_samples {
 public:
  exact_samples(const vec3<T>& I, const body_state<T>& initial, const T& total_time, int finest)
      : total_(total_time), finest_(finest) {
    if (!(total_time > 0)) throw std::invalid_argument("the total time must be positive");
    if (finest < 0 || finest > 24) throw std::invalid_argument("the finest grid must be 2^0 … 2^24 steps");
    const exact_free_body<T> exact(I, initial);
    const long n = 1L << finest;
    Q_.reserve(static_cast<std::size_t>(n) + 1);
    error_.reserve(static_cast<std::size_t>(n) + 1);
    for (long k = 0; k <= n; ++k) {
      const auto r = exact.evaluate(total_time * static_cast<T>(k) / static_cast<T>(n));
      Q_.push_back(r.state.Q);
      error_.push_back(3 * r.error_estimate);  // max abs entry → R^9 distance
    }
  }
  const T& total_time() const { return total_; }
  int finest() const { return finest_; }
  /// Attitude at step k of a run with 2^level steps (level ≤ finest).
  const mat3<T>& at(int level, long k) const { return Q_[static_cast<std::size_t>(k << (finest_ - level))]; }
  /// Estimated R^9 error of at(level, k).
  const T& error(int level, long k) const { return error_[static_cast<std::size_t>(k << (finest_ - level))]; }
  /// Estimated error of the mean attitude error of a run with 2^level steps (the mean of the samples').
  T mean_error(int level) const {
    const long n = 1L << level;
    T sum = 0;
    for (long k = 1; k <= n; ++k) sum += error(level, k);
    return sum / static_cast<T>(n);
  }

 private:
  T total_;
  int finest_;
  std::vector<mat3<T>> Q_;
  std::vector<T> error_;
};

/// Mean attitude error of a run with 2^level steps of size T/2^level.
template <class T>
T mean_attitude_error(const composition_stepper<T>& stepper, const body_state<T>& initial, const exact_samples<T>& exact,
                      int level) {
  if (level < 0 || level > exact.finest()) throw std::invalid_argument("step level outside the sampled grid");
  const long n = 1L << level;
  const T h = exact.total_time() / static_cast<T>(n);
  body_state<T> s = initial;
  T sum = 0;
  for (long k = 1; k <= n; ++k) {
    stepper.step(s, h);
    sum += distance(s.Q, exact.at(level, k));
  }
  return sum / static_cast<T>(n);
}

/// CPU seconds per unit of simulated time for step h, measured on repeated runs of at least
/// `minimum_seconds` (stepping only, no error evaluation).
template <class T>
double cpu_seconds_per_unit_time(const composition_stepper<T>& stepper, const body_state<T>& initial, const T& h,
                                 double minimum_seconds = 0.02) {
  using clock = std::chrono::steady_clock;
  long steps = 0;
  const auto start = clock::now();
  double elapsed = 0;
  body_state<T> s = initial;
  do {
    for (int k = 0; k < 256; ++k) stepper.step(s, h);
    steps += 256;
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  } while (elapsed < minimum_seconds);
  volatile double sink = static_cast<double>(s.G[0]);
  (void)sink;
  return elapsed / (static_cast<double>(steps) * static_cast<double>(h));
}

/// Least-squares slope of log(error) against log(h) over the given points.
inline double fitted_slope(const std::vector<double>& h, const std::vector<double>& error) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]), y = std::log(error[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

struct protocol_point {
  double h = 0, h_over_cost = 0, error = 0;
  double reference_error = 0;  ///< the exact flow's estimated share of `error`
  /// The error belongs to the scheme: well above the reference's.
  bool attributable() const { return error > reference_margin * reference_error; }
};

struct order_measurement {
  std::vector<protocol_point> points;  ///< one per level, coarse to fine
  double slope = 0;                    ///< fitted over the last `fit_points` attributable points (NaN if < 2)
};

/// Errors at h = T/2^level for level = first … last, and the fitted order over the finest
/// `fit_points` of them (the asymptotic range).
template <class T>
order_measurement measure_order(const schemes::scheme_table& table, const vec3<T>& I, const body_state<T>& initial,
                                const T& total_time, int first, int last, int fit_points) {
  if (first < 0 || last < first || last > 20) throw std::invalid_argument("step levels must satisfy 0 ≤ first ≤ last ≤ 20");
  const composition_stepper<T> stepper(table, I);
  const exact_samples<T> exact(I, initial, total_time, last);
  order_measurement m;
  for (int level = first; level <= last; ++level) {
    const double h = static_cast<double>(total_time) / static_cast<double>(1L << level);
    m.points.push_back({h, h / stepper.cost(), static_cast<double>(mean_attitude_error(stepper, initial, exact, level)),
                        static_cast<double>(exact.mean_error(level))});
  }
  std::vector<double> hs, es;
  for (std::size_t i = m.points.size() - static_cast<std::size_t>(std::min<int>(fit_points, static_cast<int>(m.points.size())));
       i < m.points.size(); ++i)
    if (m.points[i].attributable()) {
      hs.push_back(m.points[i].h);
      es.push_back(m.points[i].error);
    }
  m.slope = hs.size() >= 2 ? fitted_slope(hs, es) : std::nan("");
  return m;
}

}  // namespace rotlie::models
