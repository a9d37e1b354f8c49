#pragma once
// The spin–orbit scene stepped in any scalar with any of its integrators, an observer called after
// each step: the one loop behind spin_run, the tests and bench/spin_bench.
#include <algorithm>
#include <functional>
#include <string>

#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::runs {

template <class T>
struct spin_outcome {
  models::body_state<T> state;
  T t{};
  double cpu_s = 0;       ///< CPU seconds of the stepping (observer included)
  long evaluations = 0;  ///< torque evaluations
};

/// The body's moments in T, each read once from its exact text.
template <class T>
models::vec3<T> spin_moments_in(const spin_body& body) {
  std::string text = body.moments;
  std::replace(text.begin(), text.end(), ',', ' ');
  return models::moments_from_text<T>(text);
}

/// Called after step k with the time and the body's state.
template <class T>
using spin_observer = std::function<void(long, const T&, const models::body_state<T>&)>;

/// `steps` steps of length h (time units: the orbital period is 2π) from `start` at t = 0, calling
/// obs(k, t, state) after step k when given. An Odeint method takes h (or m.first_step) as its first trial
/// step and chooses its own steps; with an observer it lands on every k h, without one it runs straight to
/// steps·h. Compiled once per scalar (double, long double, float128) in spin_orbit_stepping.cpp.
template <class T>
spin_outcome<T> step_spin_orbit(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start, const T& h,
                                long steps, const spin_observer<T>& obs = {});

extern template spin_outcome<double> step_spin_orbit(const spin_method&, const models::vec3<double>&, const double&,
                                                      const models::body_state<double>&, const double&, long, const spin_observer<double>&);
extern template spin_outcome<long double> step_spin_orbit(const spin_method&, const models::vec3<long double>&, const long double&,
                                                           const models::body_state<long double>&, const long double&, long,
                                                           const spin_observer<long double>&);
extern template spin_outcome<quad> step_spin_orbit(const spin_method&, const models::vec3<quad>&, const quad&,
                                                             const models::body_state<quad>&, const quad&, long,
                                                             const spin_observer<quad>&);

}  // namespace rotlie::runs
