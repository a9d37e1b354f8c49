#pragma once
// Liquid water at a temperature: rigid TIP3P (the liquid-water scene's box and potential) run by a
// thermostatted splitting (thermostats/thermostatted_bodies.hpp) from the scene's equilibrated start.
// The first fifth of the run lets the thermostat settle at its target; over the rest it measures what
// users of NVT sampling ask for (issue: "what configurational averages cost at a given accuracy"):
//   the translational and rotational kinetic temperatures (equipartition: 2K_t/((3N − 3 or 3N) k),
//   2K_r/(3N k)), the configurational temperatures (configurational_temperature.hpp), the potential
//   energy per molecule, g_OO's first peak, and the diffusion coefficient from the centres' mean squared
//   displacement (the box's centre of mass removed); each with its standard error from 10 blocks.
#include <chrono>
#include <cmath>
#include <ctime>
#include <string>
#include <vector>

#include "rotlie/models/ensemble_statistics.hpp"
#include "rotlie/models/configurational_temperature.hpp"
#include "rotlie/models/scenes/liquid_water_experiment.hpp"

namespace rotlie::models {

struct liquid_water_nvt_options {
  double kelvin = 300;
  double friction_per_ps = 1;  ///< Langevin γ
  double tau_ps = 0.1;         ///< Nosé–Hoover chains' period
  int chain_length = 3;
  std::uint64_t seed = 1;
  long probe_every = 20;       ///< steps between configurational-temperature probes and g(r) frames (4 evaluations each)
};

struct liquid_water_nvt_result {
  std::string integrator, table;
  double h_fs = 0, kelvin = 0;
  int f = 1;
  long molecules = 0, steps = 0, measured_steps = 0, probes = 0;
  mean_error translational_K, rotational_K, configurational_translational_K, configurational_rotational_K, potential_per_molecule;
  /// Langevin: the kinetic temperatures right after the O-step (BAOAB's mid-step; 3N degrees of freedom
  /// each, the noise not keeping the total momentum); NaN for chains
  mean_error translational_after_o_K{std::nan(""), std::nan("")}, rotational_after_o_K{std::nan(""), std::nan("")};
  double rdf_peak_r = 0, rdf_peak_g = 0;
  double diffusion = 0;         ///< 10⁻⁵ cm²/s
  double extended_drift = 0;    ///< Nosé–Hoover: |H_ext(end) − H_ext(settled)| / N, kcal/mol (0 for Langevin)
  double ms_per_step = 0, cpu_ms_per_step = 0;  ///< the steps alone (probes excluded)
};

/// The run of `o.integrator` (which must carry a thermostat) at nvt.kelvin from `start`.
inline liquid_water_nvt_result run_liquid_water_nvt(const liquid_water_run_options& o, const liquid_water_nvt_options& nvt,
                                                    const rigid_bodies_state<double>& start, const liquid_water_progress& progress) {
  check_liquid_water_options(o);
  if (!o.integrator.thermostat) throw std::invalid_argument("integrator " + o.integrator.name + " has no thermostat (-BAOAB, -OBABO, -NHC)");
  const auto model = tip3p<double>();
  const auto w = liquid_water_potential(o.molecules, o.density, o.threads);
  const double k_B = real_units::boltz<double>();
  thermostat_parameters bath;
  bath.kT = k_B * nvt.kelvin;
  bath.friction = nvt.friction_per_ps / 1000;  // per fs
  bath.tau = nvt.tau_ps * 1000;
  bath.chain_length = nvt.chain_length;
  bath.seed = nvt.seed;
  // the chains keep the total momentum (the forces sum to zero): 3N − 3 translational degrees of freedom;
  // Langevin's noise does not: 3N
  bath.momentum_conserved = *o.integrator.thermostat == schemes::thermostat_placement::chain;
  liquid_water_nvt_result r;
  r.integrator = o.integrator.name;
  r.h_fs = o.h_fs;
  r.f = o.integrator.f;
  r.kelvin = nvt.kelvin;
  r.molecules = o.molecules;
  const long steps = std::max(10L, std::lround(o.T_ps * 1000 / o.h_fs)), settle = steps / 5;
  r.steps = steps;
  r.measured_steps = steps - settle;
  std::vector<body_kind<double>> kinds{{model.mass, model.moments, o.rotor_table}};
  with_thermostatted_integrator(o.integrator, *o.integrator.thermostat, bath, kinds, w, unit_system<double>::real(), [&](const auto& method) {
    const auto& sys = method.system();
    r.table = method.table().name;
    auto s = start;
    s.forces_current = false;
    // 10 blocks, fewer when fewer steps are measured (an empty block would count as a zero)
    const int blocks = static_cast<int>(std::min<long>(10, r.measured_steps));
    std::vector<double> tt(blocks), tr(blocks), v(blocks), f2(blocks), t2(blocks), lt(blocks), lr(blocks), to(blocks), ro(blocks);
    std::vector<long> probes_in(blocks, 0);
    oxygen_rdf rdf(std::min(10.0, w.options().box / 2), 0.02);
    seeded_random probe_random(nvt.seed ^ 0x5eedULL, 1);
    std::vector<rigid_body_state<double>> scratch;
    std::vector<vec3<double>> sites, oxygen(s.bodies.size()), q0;
    double H_settled = 0, msd_half = 0, msd_end = 0;
    double step_seconds = 0, step_cpu = 0;
    auto com = [&](const rigid_bodies_state<double>& x) {
      vec3<double> c{};
      for (const auto& b : x.bodies)
        for (int d = 0; d < 3; ++d) c[d] += b.q[d] / static_cast<double>(x.bodies.size());
      return c;
    };
    auto msd = [&](const rigid_bodies_state<double>& x) {
      const auto c = com(x);
      double m = 0;
      for (std::size_t i = 0; i < x.bodies.size(); ++i)
        for (int d = 0; d < 3; ++d) m += std::pow(x.bodies[i].q[d] - c[d] - q0[i][d], 2);
      return m / static_cast<double>(x.bodies.size());
    };
    for (long k = 0; k < steps; ++k) {
      if (o.poll) o.poll();
      const auto t0 = std::chrono::steady_clock::now();
      const std::clock_t c0 = std::clock();
      try {
        method.step(s, o.h_fs);
      } catch (const std::invalid_argument&) {
        throw std::runtime_error("the run diverged (a momentum is not finite) at h = " + schemes::message_number(o.h_fs) + " fs");
      } catch (const std::domain_error&) {
        throw std::runtime_error("the run diverged (a molecule turns beyond the exact rotor's range) at h = " + schemes::message_number(o.h_fs) + " fs");
      }
      step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      step_cpu += static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      const double V = sys.potential_energy(s);
      if (!std::isfinite(V) || !std::isfinite(sys.kinetic_energy(s)))
        throw std::runtime_error("the run diverged (energy not finite) at h = " + schemes::message_number(o.h_fs) + " fs");
      if (k + 1 == settle || (settle == 0 && k == 0)) {
        H_settled = sys.extended_energy(s);
        const auto c = com(s);
        q0.resize(s.bodies.size());
        for (std::size_t i = 0; i < s.bodies.size(); ++i)
          for (int d = 0; d < 3; ++d) q0[i][d] = s.bodies[i].q[d] - c[d];
      }
      if (k < settle) {
        if (progress && (k + 1) % 1000 == 0) progress("settling " + schemes::message_number(double(k + 1) * o.h_fs / 1000) + " ps");
        continue;
      }
      const auto b = static_cast<std::size_t>((k - settle) * blocks / r.measured_steps);
      const double n = static_cast<double>(r.measured_steps) / blocks;
      tt[b] += 2 * sys.translational_energy(s) / (sys.translational_dof(s) * k_B) / n;
      tr[b] += 2 * sys.rotational_energy(s) / (sys.rotational_dof(s) * k_B) / n;
      v[b] += V / static_cast<double>(o.molecules) / n;
      const auto [t_o, r_o] = sys.temperatures_after_o(s);
      to[b] += nvt.kelvin * t_o / n, ro[b] += nvt.kelvin * r_o / n;
      if (k - settle == r.measured_steps / 2) msd_half = msd(s);
      if ((k - settle) % nvt.probe_every == 0) {
        sys.bodies().ensure_forces(s);
        const auto c = probe_configurational(w, s.bodies, s.force, s.torque, probe_random, scratch);
        f2[b] += c.force_squared, t2[b] += c.torque_squared, lt[b] += c.translation_laplacian, lr[b] += c.rotation_laplacian;
        ++probes_in[b];
        ++r.probes;
        w.site_positions(s.bodies, sites);
        for (std::size_t i = 0; i < oxygen.size(); ++i) oxygen[i] = sites[3 * i];
        rdf.add(oxygen, w.options().box);
      }
      if (progress && (k + 1) % 1000 == 0)
        progress(schemes::message_number(double(k + 1) * o.h_fs / 1000) + " ps: T_trans " + schemes::message_number(2 * sys.translational_energy(s) / (sys.translational_dof(s) * k_B)) +
                 " K, T_rot " + schemes::message_number(2 * sys.rotational_energy(s) / (sys.rotational_dof(s) * k_B)) + " K");
    }
    msd_end = msd(s);
    if (o.integrator.thermostat == schemes::thermostat_placement::chain)
      r.extended_drift = std::abs(sys.extended_energy(s) - H_settled) / static_cast<double>(o.molecules);
    r.translational_K = ensemble_mean(tt);
    r.rotational_K = ensemble_mean(tr);
    r.potential_per_molecule = ensemble_mean(v);
    if (o.integrator.thermostat != schemes::thermostat_placement::chain) {
      r.translational_after_o_K = ensemble_mean(to);
      r.rotational_after_o_K = ensemble_mean(ro);
    }
    // configurational temperatures: the ratio of the sums, its error from the blocks' ratios
    std::vector<double> ct, cr;
    double F2 = 0, T2 = 0, LT = 0, LR = 0;
    for (int b = 0; b < blocks; ++b) {
      F2 += f2[b], T2 += t2[b], LT += lt[b], LR += lr[b];
      if (probes_in[b] > 0) ct.push_back(f2[b] / lt[b] / k_B), cr.push_back(t2[b] / lr[b] / k_B);
    }
    r.configurational_translational_K = {F2 / LT / k_B, ensemble_mean(ct).error};
    r.configurational_rotational_K = {T2 / LR / k_B, ensemble_mean(cr).error};
    for (const auto& [radius, g] : rdf.curve())
      if (radius > 2.4 && radius < 3.4 && g > r.rdf_peak_g) r.rdf_peak_g = g, r.rdf_peak_r = radius;
    // D = Δ MSD / (6 Δt) over the measured run's second half, Å²/fs → 10⁻⁵ cm²/s (1 Å²/fs = 10⁻¹ cm²/s)
    const double half_fs = static_cast<double>(r.measured_steps - r.measured_steps / 2) * o.h_fs;
    r.diffusion = (msd_end - msd_half) / (6 * half_fs) * 1e4;
    r.ms_per_step = 1000 * step_seconds / static_cast<double>(steps);
    r.cpu_ms_per_step = 1000 * step_cpu / static_cast<double>(steps);
    return 0;
  });
  return r;
}

}  // namespace rotlie::models
