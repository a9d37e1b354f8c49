#pragma once
// What the two van Zon–Schofield experiments share: how a run is asked for (integrator, step, length,
// ensemble, seed), the integrator built for a scene, CPU time, and an ensemble's mean ± error.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/ensemble_statistics.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/md_trajectory.hpp"

namespace rotlie::models {

/// A run in the scene's units: h in its time unit (fs for the real-unit scenes), T in a thousand of them.
struct md_run_options {
  md_integrator integrator = md_integrator_of("SIER2", "Strang-TV", "exact");  ///< the splitting and the rotor's kind, resolved by the caller
  const schemes::scheme_table* rotor_table = nullptr;      ///< X resolved for the body (a dedicated table), or null
  double h_fs = 0;                                  ///< the step h itself (not h/f)
  double T_ps = 0;                                  ///< simulated time per run
  long runs = 1;                                    ///< ensemble size
  std::uint64_t seed = 1;
  long every = 0;  ///< > 0: the first run's trajectory every `every` steps (md_ensemble_cost::trajectory)
  std::function<void(long done, long runs)> progress;  ///< after each run, may be empty
  std::function<void()> poll;  ///< every 64 steps of a run, may be empty; throws to abandon the ensemble (a stop asked for)
};

/// Steps of one run: T/h rounded to the nearest whole number (at least 1).
inline long md_steps(const md_run_options& o) {
  if (!(o.h_fs > 0) || !(o.T_ps > 0) || o.runs < 1) throw std::invalid_argument("h, T and runs must be positive");
  const double n = std::round(o.T_ps * 1000 / o.h_fs);
  if (!(n < 1e12)) throw std::invalid_argument("T/h is too many steps");
  return std::max(1L, static_cast<long>(n));
}

/// The composition of o.integrator for the scene's body, potential and units, handed to visit.
template <class T, class Scene, class Visitor>
auto with_scene_integrator(const Scene& scene, const md_run_options& o, Visitor&& visit) {
  return with_md_integrator<T>(o.integrator, std::vector<body_kind<T>>{{scene.mass, scene.moments, o.rotor_table}}, scene.potential,
                               scene.units, std::forward<Visitor>(visit));
}

/// What every ensemble measures of its integrator besides the physics.
struct md_ensemble_cost {
  int f = 0;                ///< force evaluations per step (the h/f of vZS)
  long steps = 0;           ///< per run
  double cpu_s_per_ps = 0;  ///< stepping only
  double round_off = 0;     ///< the unit round-off ε of the scalar the runs used
  md_trajectory trajectory;  ///< the first run's, body 0, when md_run_options::every > 0
};

/// The ensemble loop of the experiments: f and steps into `cost`, then each run from
/// scene.initial(seed, run) handed to one_run(x, step), where step(x, observers...) integrates the
/// run with its CPU time counted; one_run returns false to end the ensemble (progress is shown
/// after each run that did not).
template <class Scene, class Method, class OneRun>
void run_ensemble(const Scene& scene, const md_run_options& o, const Method& method, long steps, md_ensemble_cost& cost, OneRun&& one_run) {
  using T = typename Method::scalar;
  cost.f = method.cost();
  cost.steps = steps;
  cost.round_off = static_cast<double>(std::numeric_limits<T>::epsilon());
  const T h = T(o.h_fs);
  double cpu = 0;
  long run = 0;
  cost.trajectory = {};
  cost.trajectory.every = o.every;
  // the first run's samples, its start included (taken after the run's own preparation, e.g. its forces)
  auto sample = [&](long k, const T&, const rigid_bodies_state<T>& s) {
    if (k % o.every == 0)
      cost.trajectory.record(o.h_fs * static_cast<double>(k) / 1000, s.bodies[0], method.system().kinetic_energy(s) + s.potential, s.potential);
    return true;
  };
  auto poll = [&](long k, const T&, const rigid_bodies_state<T>&) {
    if (k % 64 == 0 && o.poll) o.poll();
  };
  auto step = [&](rigid_bodies_state<T>& x, auto&... observers) {
    const bool sampled = run == 0 && o.every > 0;
    if (sampled) sample(0, T(0), x);
    const double c0 = thread_cpu_seconds();
    if (sampled)
      integrate(method, x, h, steps, observers..., sample, poll);
    else
      integrate(method, x, h, steps, observers..., poll);
    cpu += thread_cpu_seconds() - c0;
  };
  for (run = 0; run < o.runs; ++run) {
    auto x = scene.initial(o.seed, static_cast<std::uint64_t>(run));
    if (!one_run(x, step)) break;
    if (o.progress) o.progress(run + 1, o.runs);
  }
  cost.cpu_s_per_ps = cpu / (static_cast<double>(o.runs) * o.T_ps);
}

}  // namespace rotlie::models
