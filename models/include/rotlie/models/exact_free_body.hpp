#pragma once
// The exact motion of the free rigid body, for any |G| and any scale of the moments, with an
// error estimate on every evaluation and a stated time limit.
//  - Scale-free: G and I are scaled by powers of two (exactly) to O(1); the motion with G scaled by
//    s is the motion at time s·t, with I scaled by c the motion at time t/c.
//  - The closed form itself (detail::free_body_motion, REFERENCE.md §2.3 with the reformulations
//    listed there) keeps its relative accuracy near the separatrix, near spherical, symmetric, thin
//    and flat bodies; what remains is the round-off of the phase angles: an evaluation's error is
//    estimated as ε·4·(2 + (|u| + |ψ parts|)·√(1 − n)), ε the unit round-off of the scalar used (√(1 − n):
//    the axis ratio of the ellipse L⊥ runs on, large only in the thin island about z of a body with I_y ≈ I_z).
//    The one input of the phase that cancels, D_y (zero on the separatrix), is exact to a few ε
//    relative at any distance from the separatrix (exact_energy_difference.hpp); its share of the
//    phase error, ≤ |u|·|δm_c/m_c|/2, is within that term. Where its terms underflow, so that this
//    cannot be vouched for, the state counts as unrepresentable (float128, or estimate 1).
//  - When that estimate exceeds the requested accuracy (long times, fast spin of a thin body) and a
//    wider scalar exists (double, long double → float128), the evaluation is redone in float128;
//    the wider motion is built once, on first need.
//  - Beyond a phase of 2^60 radians (|ω| |t|), where even float128 keeps no more than ~15 digits of
//    the angle, at() refuses with std::domain_error instead of returning digits it cannot know.

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "rotlie/models/free_body_motion.hpp"
#include "rotlie/models/rigid_body.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::models {

template <class T>
class exact_free_body {
  static constexpr bool has_wider = !std::is_same_v<T, quad>;
  using wide = std::conditional_t<has_wider, quad, T>;

 public:
  /// Safety factor of the estimate over the measured errors (exact_flow_regimes_test; in 88,000 random
  /// states over every regime the largest measured error was 0.92 of the estimate).
  static constexpr double estimate_factor = 4;
  /// The largest phase |ω|·|t| (radians) that at() accepts.
  static constexpr double max_phase = 1152921504606846976.0;  // 2^60

  /// `accuracy`: the absolute error (on Q, and on G relative to |G|) above which an evaluation is
  /// redone in float128; the estimate returned with each state says what was reached.
  exact_free_body(const vec3<T>& I, const body_state<T>& initial, double accuracy = 1e-12)
      : initial_(checked(I, initial)),
        accuracy_(accuracy),
        eG_(exponent(std::max({abs_(initial.G[0]), abs_(initial.G[1]), abs_(initial.G[2])}))),
        eI_(exponent(std::max({I[0], I[1], I[2]}))),
        I_{ldexp_(I[0], -eI_), ldexp_(I[1], -eI_), ldexp_(I[2], -eI_)},
        G_{ldexp_(initial.G[0], -eG_), ldexp_(initial.G[1], -eG_), ldexp_(initial.G[2], -eG_)},
        omega_(T(std::sqrt(static_cast<double>(dot(G_, G_)))) / std::min({I_[0], I_[1], I_[2]})),  // |ω| ≤ |G|/I_min
        core_(I_, G_, initial.Q) {}

  /// The elliptic parameter m of the momentum's motion (0 for a steady rotation, 1 on the separatrix).
  T parameter() const { return core_.parameter(); }
  /// The complementary parameter m_c = 1 − m, computed directly (exact 0 on the separatrix).
  T complementary_parameter() const { return core_.complementary_parameter(); }

  /// The largest |t| that at() accepts.
  T max_time() const {
    if (!(omega_ > 0)) return std::numeric_limits<T>::infinity();  // a body at rest stays so forever
    return ldexp_(T(max_phase) / omega_, eI_ - eG_);
  }

  struct result {
    body_state<T> state;
    T error_estimate;  ///< estimated max abs error of the entries of Q and of G/|G|
  };

  /// The state at time t and its estimated error; throws std::domain_error beyond max_time().
  result evaluate(const T& t) const {
    using std::abs;
    using std::isfinite;
    if (!isfinite(static_cast<double>(t)) || abs(t) > max_time())
      throw std::domain_error("the exact flow is limited to |ω|·|t| ≤ 2^60 rad (|t| ≤ " +
                              schemes::message_number(static_cast<double>(max_time())) + " here)");
    if (!(omega_ > 0)) return {initial_, bound<T>(T(0))};  // G = 0: the body does not turn (the estimate's floor, as everywhere)
    const T tau = ldexp_(t, eG_ - eI_);
    const auto e = core_.at(tau);
    // a state the scalar cannot represent has no estimate in it (1: nothing is known)
    T estimate = core_.representable() ? bound<T>(e.phase * core_.amplification()) : T(1);
    if constexpr (has_wider) {
      if (!(estimate <= T(accuracy_))) {
        auto w = wide_.p.load();
        if (!w) {
          vec3<wide> Iw, Gw;
          mat3<wide> Qw;
          for (std::size_t i = 0; i < 3; ++i) Iw[i] = wide(I_[i]), Gw[i] = wide(G_[i]);
          for (std::size_t i = 0; i < 9; ++i) Qw.a[i] = wide(initial_.Q.a[i]);
          w = std::make_shared<const detail::free_body_motion<wide>>(Iw, Gw, Qw);
          wide_.p.store(w);
        }
        const auto ew = w->at(wide(tau));
        body_state<T> s;
        for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] = static_cast<T>(ew.state.Q.a[i]);
        for (std::size_t i = 0; i < 3; ++i) s.G[i] = static_cast<T>(ew.state.G[i]);
        const wide wide_estimate = w->representable() ? bound<wide>(ew.phase * w->amplification()) : wide(1);
        return {unscale(s), std::max(static_cast<T>(wide_estimate), std::numeric_limits<T>::epsilon())};
      }
    }
    return {unscale(e.state), estimate};
  }

  /// The state at time t (any sign, |t| ≤ max_time()).
  body_state<T> at(const T& t) const { return evaluate(t).state; }
  /// The estimated error of at(t).
  T error_bound(const T& t) const { return evaluate(t).error_estimate; }

 private:
  template <class S>
  static S bound(const S& phase) {
    return std::numeric_limits<S>::epsilon() * (2 * S(estimate_factor) + S(estimate_factor) * phase);
  }
  static const body_state<T>& checked(const vec3<T>& I, const body_state<T>& initial) {
    validate_moments(I);
    using std::isfinite;
    for (const auto& g : initial.G)
      if (!isfinite(static_cast<double>(g))) throw std::invalid_argument("the initial momentum must be finite");
    for (const auto& q : initial.Q.a)
      if (!isfinite(static_cast<double>(q))) throw std::invalid_argument("the initial attitude must be finite");
    return initial;
  }
  static int exponent(const T& x) {
    using std::ilogb;
    return x > 0 ? static_cast<int>(ilogb(x)) : 0;
  }
  static T abs_(const T& x) {
    using std::abs;
    return abs(x);
  }
  static T ldexp_(const T& x, int e) {
    using std::ldexp;
    return ldexp(x, e);
  }
  body_state<T> unscale(body_state<T> s) const {
    for (auto& g : s.G) g = ldexp_(g, eG_);
    return s;
  }

  body_state<T> initial_;
  double accuracy_;
  int eG_ = 0, eI_ = 0;
  vec3<T> I_{}, G_{};
  T omega_ = 0;
  detail::free_body_motion<T> core_;
  struct wide_cache {  // the float128 motion, built on first need; copies share it
    mutable std::atomic<std::shared_ptr<const detail::free_body_motion<wide>>> p;
    wide_cache() = default;
    wide_cache(const wide_cache& o) : p(o.p.load()) {}
    wide_cache& operator=(const wide_cache& o) {
      p.store(o.p.load());
      return *this;
    }
  };
  wide_cache wide_;
};

}  // namespace rotlie::models
