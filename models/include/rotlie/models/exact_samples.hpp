#pragma once
// The exact attitude sampled once on the finest grid of a protocol run and reused for every coarser
// step, with the exact flow's own error estimate per sample (exact_free_body::evaluate), so that no
// point of an order fit measures the reference instead of the scheme (LV section 4.1).
#include <stdexcept>
#include <vector>

#include "rotlie/models/exact_free_body.hpp"

namespace rotlie::models {

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

}  // namespace rotlie::models
