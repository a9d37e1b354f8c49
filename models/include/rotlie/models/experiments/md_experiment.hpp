#pragma once
// What the two van Zon–Schofield experiments share: how a run is asked for (integrator, step, length,
// ensemble, seed), the integrator built for a scene, CPU time, and an ensemble's mean ± error.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/md_integrators.hpp"

namespace rotlie::models {

struct md_run_options {
  std::string integrator;                           ///< SIER2, SIER4, MRDL, SEJ4, SIER2/X, SIER4/X
  const schemes::scheme_table* rotor_table = nullptr;  ///< X resolved for the body (a dedicated table), or null
  double h_fs = 0;                                  ///< the step h itself (not h/f)
  double T_ps = 0;                                  ///< simulated time per run
  long runs = 1;                                    ///< ensemble size
  std::uint64_t seed = 1;
  std::function<void(long done, long runs)> progress;  ///< after each run, may be empty
};

/// Steps of one run: T/h rounded to the nearest whole number (at least 1).
inline long md_steps(const md_run_options& o) {
  if (!(o.h_fs > 0) || !(o.T_ps > 0) || o.runs < 1) throw std::invalid_argument("h, T and runs must be positive");
  const double n = std::round(o.T_ps * 1000 / o.h_fs);
  if (!(n < 1e12)) throw std::invalid_argument("T/h is too many steps");
  return std::max(1L, static_cast<long>(n));
}

/// Mean and standard error of the mean (sample standard deviation / √n; 0 for one value).
struct mean_error {
  double mean = 0, error = 0;
};

inline mean_error ensemble_mean(const std::vector<double>& x) {
  mean_error r;
  if (x.empty()) return {std::nan(""), std::nan("")};
  for (double v : x) r.mean += v;
  r.mean /= static_cast<double>(x.size());
  if (x.size() < 2) return r;
  double ss = 0;
  for (double v : x) ss += (v - r.mean) * (v - r.mean);
  r.error = std::sqrt(ss / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
  return r;
}

/// The composition of o.integrator for the scene's body and potential, handed to visit.
template <class T, class Scene, class Visitor>
auto with_scene_integrator(const Scene& scene, const md_run_options& o, Visitor&& visit) {
  const md_integrator spec = md_integrator_named(o.integrator);
  return with_md_integrator<T>(spec, o.rotor_table, scene.mass, scene.moments, scene.potential, std::forward<Visitor>(visit));
}

}  // namespace rotlie::models
