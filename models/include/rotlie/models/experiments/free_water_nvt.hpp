#pragma once
// The free water molecule at a temperature: each run of the ensemble is one molecule without forces,
// its own thermostat (its own noise stream, its own chains) from the scene's canonical start. The first
// fifth of a run settles; over the rest the molecule's translational and rotational temperatures
// (2K/3k_B each) are averaged in time, then over the runs. At the runs' ends the scaled momenta
// p_i/√(m kT) and G_i/√(I_i kT) of every run are tested against the standard normal (Kolmogorov–
// Smirnov): the Maxwell–Boltzmann distribution a thermostat must reach. Langevin's noise reaches it by
// construction; a single Nosé–Hoover thermostat on a free molecule would not (its momenta would keep
// a memory of the start), a chain may: the distance says which.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/models/scenes/free_water.hpp"
#include "rotlie/models/ensemble_statistics.hpp"
#include "rotlie/models/md_integrators.hpp"

namespace rotlie::models {

struct free_water_nvt_result {
  std::string table;
  double kelvin = 0;
  long steps = 0;
  mean_error translational_K, rotational_K;
  double ks_translational = 0, ks_rotational = 0;  ///< Kolmogorov–Smirnov distances of the runs' ends
  double ks_critical = 0;                          ///< its critical value at level 0.001 (3 × runs samples)
  double cpu_s_per_ps = 0;
};

/// o's runs of o.integrator (with its thermostat) on free water at `kelvin` (friction per fs, tau fs).
inline free_water_nvt_result run_free_water_nvt(const md_run_options& o, double kelvin, double friction_per_fs, double tau_fs, int chain_length = 3) {
  if (!o.integrator.thermostat) throw std::invalid_argument("integrator " + o.integrator.name + " has no thermostat");
  const free_water<double> scene;
  const double k_B = real_units::boltz<double>(), kT = k_B * kelvin / scene.units.mvv2e;
  free_water_nvt_result r;
  r.kelvin = kelvin;
  r.steps = md_steps(o);
  const long settle = r.steps / 5;
  std::vector<double> trans, rot, p_scaled, G_scaled;
  const std::clock_t c0 = std::clock();
  for (long run = 0; run < o.runs; ++run) {
    thermostat_parameters bath;
    bath.kT = k_B * kelvin;
    bath.friction = friction_per_fs;
    bath.tau = tau_fs;
    bath.chain_length = chain_length;
    bath.momentum_conserved = false;  // one free molecule: its momentum is a thermostatted degree of freedom
    std::uint64_t key = static_cast<std::uint64_t>(run);
    bath.seed = o.seed ^ splitmix64(key);
    with_thermostatted_integrator(o.integrator, *o.integrator.thermostat, bath, {{scene.mass, scene.moments, o.rotor_table}}, scene.potential,
                                  scene.units, [&](const auto& method) {
      r.table = method.table().name;
      const auto& sys = method.system();
      auto s = scene.initial(o.seed, static_cast<std::uint64_t>(run));
      double t_sum = 0, r_sum = 0;
      for (long k = 0; k < r.steps; ++k) {
        if (o.poll && k % 64 == 0) o.poll();
        method.step(s, o.h_fs);
        if (k < settle) continue;
        t_sum += 2 * sys.translational_energy(s) / (3 * k_B);
        r_sum += 2 * sys.rotational_energy(s) / (3 * k_B);
      }
      const double n = static_cast<double>(r.steps - settle);
      trans.push_back(t_sum / n);
      rot.push_back(r_sum / n);
      const auto& b = s.bodies.front();
      for (int i = 0; i < 3; ++i) {
        p_scaled.push_back(b.p[i] / std::sqrt(scene.mass * kT));
        G_scaled.push_back(b.rot.G[i] / std::sqrt(scene.moments[i] * kT));
      }
      return 0;
    });
    if (o.progress) o.progress(run + 1, o.runs);
  }
  r.translational_K = ensemble_mean(trans);
  r.rotational_K = ensemble_mean(rot);
  r.ks_translational = normal_ks_distance(p_scaled);
  r.ks_rotational = normal_ks_distance(G_scaled);
  r.ks_critical = ks_critical_0_001(G_scaled.size());
  r.cpu_s_per_ps = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / (static_cast<double>(o.runs) * o.T_ps);
  return r;
}

}  // namespace rotlie::models
