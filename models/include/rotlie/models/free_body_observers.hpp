#pragma once
// Observers of a free-body run (models/integrate.hpp calls obs(k, t, state) after step k): the
// mean attitude error against the exact motion, sampled or evaluated, with the reference's own
// error estimate; the drift of the energy and of |G|; and a guard that stops a run that fails.
// None allocates: they add up numbers as the run goes.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/exact_samples.hpp"

namespace rotlie::models {

/// The running mean of an attitude distance and of the reference's estimated error at each step:
/// what the two attitude-error observers below share.
template <class T>
class attitude_error_tally {
 public:
  T mean() const { return sum_ / static_cast<T>(steps_); }
  /// The reference's estimated share of mean().
  T reference_mean() const { return reference_sum_ / static_cast<T>(steps_); }
  long steps() const { return steps_; }

 protected:
  void add(const T& distance, const T& reference_error) {
    sum_ += distance;
    reference_sum_ += reference_error;
    ++steps_;
  }

 private:
  T sum_{}, reference_sum_{};
  long steps_ = 0;
};

/// Mean R^9 distance of the attitude from exact samples, for a run of 2^level steps of T/2^level
/// (LV section 4.1), and the mean of the samples' estimated errors.
template <class T>
class sampled_attitude_error : public attitude_error_tally<T> {
 public:
  sampled_attitude_error(const exact_samples<T>& exact, int level) : exact_(&exact), level_(level) {
    if (level < 0 || level > exact.finest()) throw std::invalid_argument("step level outside the sampled grid");
  }
  void operator()(long k, const T&, const body_state<T>& s) {
    this->add(distance(s.Q, exact_->at(level_, k)), exact_->error(level_, k));
  }

 private:
  const exact_samples<T>* exact_;
  int level_;
};

/// Mean R^9 distance of the attitude from the exact flow evaluated at every step's time, and the
/// mean of the flow's estimated errors.
template <class T>
class flow_attitude_error : public attitude_error_tally<T> {
 public:
  explicit flow_attitude_error(const exact_free_body<T>& exact) : exact_(&exact) {}
  void operator()(long, const T& t, const body_state<T>& s) {
    const auto r = exact_->evaluate(t);
    this->add(distance(s.Q, r.state.Q), 3 * r.error_estimate);  // max abs entry → R^9 distance
  }

 private:
  const exact_free_body<T>* exact_;
};

/// The largest relative drifts of the energy and of |G| from the initial state over the run.
/// Every stage of a free-body scheme is an exact rotation, so |G| drifts by round-off only.
template <class T>
class invariant_drift {
 public:
  invariant_drift(const vec3<T>& I, const body_state<T>& initial)
      : I_(I), e0_(kinetic_energy(I, initial.G)), g0_(norm(initial.G)) {}
  void operator()(long, const T&, const body_state<T>& s) {
    using std::abs;
    const T de = abs(kinetic_energy(I_, s.G) - e0_) / e0_, dg = abs(norm(s.G) - g0_) / g0_;
    energy_ = std::max(energy_, static_cast<double>(de));
    momentum_ = std::max(momentum_, static_cast<double>(dg));
  }
  double energy_error() const { return energy_; }    ///< max |E − E0| / E0
  double momentum_error() const { return momentum_; }  ///< max ||G| − |G0|| / |G0|

 private:
  static T norm(const vec3<T>& G) {
    using std::sqrt;
    return sqrt(dot(G, G));
  }
  vec3<T> I_;
  T e0_, g0_;
  double energy_ = 0, momentum_ = 0;
};

/// True when an entry of the state is NaN or infinite.
template <class T>
bool not_finite(const body_state<T>& s) {
  using std::isfinite;
  for (const auto& x : s.Q.a)
    if (!isfinite(x)) return true;
  for (const auto& x : s.G)
    if (!isfinite(x)) return true;
  return false;
}

/// Stops the run at the first step whose state the predicate rejects (a non-finite value, a
/// threshold passed by another observer's figure): put it first, so that the observers after it
/// never see that state.
template <class Failed>
class stop_when {
 public:
  explicit stop_when(Failed failed) : failed_(std::move(failed)) {}
  template <class Scalar, class State>
  bool operator()(long k, const Scalar&, const State& x) {
    if (!failed_(x)) return true;
    stopped_at_ = k;
    return false;
  }
  bool stopped() const { return stopped_at_ > 0; }
  long stopped_at() const { return stopped_at_; }  ///< the failing step, 0 if none

 private:
  Failed failed_;
  long stopped_at_ = 0;
};

/// The guard of every free-body run: stop at the first non-finite state.
template <class T>
auto stop_unless_finite() {
  return stop_when([](const body_state<T>& s) { return not_finite(s); });
}

}  // namespace rotlie::models
