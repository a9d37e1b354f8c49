#pragma once
// The exact free rotation as a step: advance(state, t) takes a body from its state now to its state
// a time t later, keeping the body's constants between calls (one call per body per free flight).
// The free flight of SIER2/SIER4 (van Zon & Schofield eq. 5b) and the reference of the free-water scene.
#include "rotlie/models/exact_free_body.hpp"

namespace rotlie::models {

template <class T>
class exact_free_rotation {
 public:
  explicit exact_free_rotation(const vec3<T>& I, double accuracy = 1e-12) : I_(I), accuracy_(accuracy) {
    validate_moments(I_);
  }

  const vec3<T>& moments() const { return I_; }

  /// s ← the exact motion from s over time t; returns the evaluation's error estimate
  /// (max abs entry of Q and of G/|G|).
  T advance(body_state<T>& s, const T& t) const {
    const auto r = exact_free_body<T>(I_, s, accuracy_).evaluate(t);
    s = r.state;
    return r.error_estimate;
  }

 private:
  vec3<T> I_;
  double accuracy_;
};

}  // namespace rotlie::models
