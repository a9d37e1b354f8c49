#pragma once
// The clock of a state whose system depends on time (H(x, t) made autonomous by adding t to the phase
// space). Summing the free flights' c h stage by stage loses up to an ulp of t per stage, and over
// 10⁶ steps of a body locked to its orbit's phase that drift becomes an attitude error. The engine
// (composition.hpp) instead writes each stage's time from the step count: origin + n h + C_j h, C_j
// the sum of the time coefficients up to stage j, and origin + (n + 1) h once the step's time is all
// spent, so that after k steps from t = 0 the clock reads fl(k h) exactly.
namespace rotlie::models {

template <class T>
struct step_clock {
  T origin{};        ///< the time at the start of the count
  T h{};             ///< the step the count is of
  long steps = 0;    ///< steps of h taken since origin
  T written{};       ///< the time the engine wrote last
  bool counting = false;

  /// At the start of a step of size h from time t: a new count when there was none, when the step
  /// changed, or when t was set from outside since the engine wrote it.
  void begin(const T& t, const T& step) {
    if (counting && step == h && t == written) return;
    origin = t;
    h = step;
    steps = 0;
    counting = true;
  }

  /// The time within the current step after a cumulative coefficient c (0 < c < 1).
  T within(const T& c) const { return origin + (T(steps) * h + c * h); }

  /// The time at the end of the current step.
  T end() const { return origin + T(steps + 1) * h; }

  /// Closes the current step; returns its end time, which the state's t must hold.
  T close() {
    ++steps;
    written = origin + T(steps) * h;
    return written;
  }
};

}  // namespace rotlie::models
