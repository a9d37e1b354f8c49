#pragma once
// Where a held simulation's integrate(t) stops: the whole steps of h from time 0 whose end is at most
// t, a step whose end overshoots t by round-off only (a billionth of h, or 8 ulps of t/h) counted.
// Time is k·h from the integer count k, never accumulated, so that one call to t and two calls
// (t/2, then t) take the same steps and give the same bits.

namespace rotlie::runs {

/// The step count of time t (units of h); throws std::invalid_argument naming `what` for a t that is
/// not finite, before `now` steps, or beyond 10¹⁵ steps.
long held_steps_until(double t, double h, long now, const char* what);

}  // namespace rotlie::runs
