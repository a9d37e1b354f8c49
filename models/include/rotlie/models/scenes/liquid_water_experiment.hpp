#pragma once
// The liquid-water experiment of vZS section V.C (Fig. 1): N TIP3P molecules at 297 K and
// 0.9973 g/cm³, equilibrated from a lattice (or read from a state file), then NVE runs of one
// integrator; per run the rms fluctuation of the total energy over that of the potential energy
// (ΔE/ΔV), sampled every step. The runs are consecutive segments of one NVE trajectory.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/md_trajectory.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_observables.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "rotlie/models/scenes/water_state_io.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::models {

struct liquid_water_run_options {
  md_integrator integrator = md_integrator_of("SIER2", "Strang-TV", "exact");  ///< the splitting and the rotor's kind, resolved by the caller
  /// SIER2/X and SIER4/X with a dedicated X: the table solved for TIP3P (tip3p_body_text); nullptr
  /// looks X up among the reference schemes.
  const schemes::scheme_table* rotor_table = nullptr;
  double h_fs = 1;          ///< the step h itself (SIER4 at h/f = 1 fs is h = 4 fs)
  double T_ps = 1;          ///< length of one run
  int runs = 9;
  long molecules = 512;
  int threads = 1;
  long every = 0;           ///< > 0: the trajectory every `every` steps from the start (result.trajectory)
  std::string state_file;   ///< read if it exists; else the equilibrated start is written there
  /// Writes a file whole (path, text); empty: write_water_state's own temporary and rename.
  std::function<void(const std::string&, const std::string&)> write_file;
  /// Called after every step (equilibration included), may be empty; throws to abandon the run (a stop asked for).
  std::function<void()> poll;
  double kelvin = 297;
  double density = 0.9973;  ///< g/cm³
  std::uint64_t seed = 1;
  double equilibration_ps = 10;
  double equilibration_h_fs = 1;
  double berendsen_tau_fs = 100;
};

struct liquid_water_run_result {
  std::string integrator;
  double h_fs = 0;
  int f = 1;
  int runs = 0;
  long molecules = 0;
  double box = 0;
  std::vector<double> ratio_percent;        ///< ΔE/ΔV per run, %
  double ratio_mean = 0, ratio_error = 0;   ///< mean and its standard error, % (NaN for one run: unknown)
  double potential_per_molecule = 0;        ///< ⟨V⟩/N over the runs, kcal/mol
  double temperature = 0;                   ///< ⟨T⟩ over the runs, K
  double ms_per_step = 0;                   ///< wall time
  double cpu_ms_per_step = 0;               ///< process CPU time (all threads together)
  long steps = 0;
  double momentum_drift = 0;                ///< max |P(t) − P(0)| over the runs, g/mol·Å/fs
  double energy_drift_per_ps = 0;           ///< (E_end − E_start)/T over all runs / N, kcal/mol/ps per molecule
  /// Per run: ΔE (kcal/mol) and the largest |K| + |V| it was computed from, whose round-off bounds what ΔE
  /// can resolve (judged by runs::verdict_of: a state far too hot leaves ΔE/ΔV measuring round-off).
  std::vector<double> dE, energy_size;
  md_trajectory trajectory;  ///< molecule 0 and the energies, the runs one after another
};

/// Line-by-line progress, may be empty.
using liquid_water_progress = std::function<void(const std::string&)>;

inline double liquid_water_box(long molecules, double density) { return cubic_box_side<double>(molecules, tip3p<double>().mass, density); }

/// Checks the numbers a user gives (the integrator is checked where its name is parsed); throws
/// std::invalid_argument with one line.
inline void check_liquid_water_options(const liquid_water_run_options& o) {
  auto finite_positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!finite_positive(o.h_fs)) throw std::invalid_argument("--h must be a positive number of fs");
  if (!finite_positive(o.T_ps)) throw std::invalid_argument("--T must be a positive number of ps");
  if (o.T_ps * 1000 / o.h_fs < 10) throw std::invalid_argument("--T must span at least 10 steps of --h (the fluctuations are rms over a run)");
  if (o.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  if (o.molecules < 2) throw std::invalid_argument("--molecules must be at least 2");
  if (o.threads < 1 || o.threads > 64) throw std::invalid_argument("--threads must be between 1 and 64");
  if (!finite_positive(o.kelvin) || !finite_positive(o.density)) throw std::invalid_argument("temperature and density must be positive");
  const double L = liquid_water_box(o.molecules, o.density);
  if (!(L > 22))
    throw std::invalid_argument("the box of " + std::to_string(o.molecules) + " molecules (" + std::to_string(L) +
                                " Å) is smaller than twice the 11 Å cutoff: use at least 365 molecules");
}

/// The potential of the scene for n molecules.
inline liquid_water<double> liquid_water_potential(long molecules, double density, int threads) {
  liquid_water_options<double> w;
  w.box = liquid_water_box(molecules, density);
  w.threads = threads;
  return liquid_water<double>(tip3p<double>(), w);
}

/// Refuses a configuration with two oxygens closer than 2 Å (molecules on top of each other).
inline void check_no_overlap(const liquid_water<double>& w, const rigid_bodies_state<double>& s) {
  std::vector<vec3<double>> x, o;
  w.site_positions(s.bodies, x);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) o.push_back(x[3 * i]);
  const auto c = closest_oxygens(o, w.options().box, 2.0);
  if (c.i >= 0)
    throw std::invalid_argument("molecules " + std::to_string(c.i + 1) + " and " + std::to_string(c.j + 1) + " overlap (O–O " +
                                std::to_string(c.distance) + " Å < 2 Å)");
}

/// The equilibrated start: read from options.state_file when it exists, else built (lattice,
/// random orientations, Berendsen equilibration with MRDL) and written there when a file is named.
inline rigid_bodies_state<double> liquid_water_start(const liquid_water_run_options& o, const liquid_water_progress& progress) {
  const auto model = tip3p<double>();
  const auto w = liquid_water_potential(o.molecules, o.density, o.threads);
  water_state_header<double> expected;
  expected.model = model.name;
  expected.molecules = o.molecules;
  expected.box = w.options().box;
  if (!o.state_file.empty() && std::filesystem::exists(o.state_file)) {
    water_state_header<double> got;
    auto s = read_water_state<double>(o.state_file, expected, got);
    check_no_overlap(w, s);
    if (progress) progress("read " + o.state_file);
    return s;
  }
  auto s = lattice_water<double>(model, o.molecules, expected.box, o.kelvin, o.seed);
  check_no_overlap(w, s);
  const long steps = std::lround(o.equilibration_ps * 1000 / o.equilibration_h_fs);
  with_md_integrator(md_integrator_of("MRDL", "Strang-TV", mrdl_rotor_table), nullptr, model.mass, model.moments, w, [&](const auto& method) {
    // the lattice start is far from equilibrium: a shorter step and a tight coupling first
    equilibrate(method, s, o.equilibration_h_fs / 4, 400, o.kelvin, 10.0, [](long, double, double) {}, 100, o.poll);
    equilibrate(method, s, o.equilibration_h_fs, steps, o.kelvin, o.berendsen_tau_fs, [&](long k, double T, double v) {
      if (progress) progress("equilibration " + schemes::message_number(static_cast<double>(k) * o.equilibration_h_fs / 1000) + " ps: T = " + schemes::message_number(T) + " K, V/N = " + schemes::message_number(v) + " kcal/mol");
    }, 500, o.poll);
    return 0;
  });
  if (!o.state_file.empty()) {
    if (o.write_file)
      o.write_file(o.state_file, water_state_text(expected, s));
    else
      write_water_state(o.state_file, expected, s);
    if (progress) progress("wrote " + o.state_file);
  }
  return s;
}

/// The NVE runs of o.integrator from `start` (see the header comment).
inline liquid_water_run_result run_liquid_water(const liquid_water_run_options& o,
                                                const rigid_bodies_state<double>& start, const liquid_water_progress& progress) {
  check_liquid_water_options(o);
  const auto model = tip3p<double>();
  const auto w = liquid_water_potential(o.molecules, o.density, o.threads);
  liquid_water_run_result r;
  r.integrator = o.integrator.name;
  r.h_fs = o.h_fs;
  r.f = o.integrator.f;
  r.runs = o.runs;
  r.molecules = o.molecules;
  r.box = w.options().box;
  const long steps = std::max(1L, std::lround(o.T_ps * 1000 / o.h_fs));
  with_md_integrator(o.integrator, o.rotor_table, model.mass, model.moments, w, [&](const auto& method) {
    const auto& sys = method.system();
    auto s = start;
    s.forces_current = false;
    const vec3<double> P0 = total_momentum(s);
    const double E_begin = sys.energy(s);
    double v_sum = 0, t_sum = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    r.trajectory.every = o.every;
    if (o.every > 0) r.trajectory.record(0.0, s.bodies[0], sys.energy(s), sys.potential_energy(s));
    for (int run = 0; run < o.runs; ++run) {
      double e_sum = 0, e_sq = 0, v_run = 0, v_sq = 0, scale = 0;
      const double e_ref = sys.energy(s), v_ref = sys.potential_energy(s);  // shifts that keep the sums well conditioned
      for (long k = 0; k < steps; ++k) {
        if (o.poll) o.poll();
        try {
          method.step(s, o.h_fs);
        } catch (const std::invalid_argument&) {  // a rotor refusing a non-finite momentum: the run blew up
          throw std::runtime_error("the run diverged (a momentum is not finite) at h = " + schemes::message_number(o.h_fs) + " fs");
        } catch (const std::domain_error&) {  // the exact rotor beyond |ω| h = 2^60 rad: a molecule spun up without bound
          throw std::runtime_error("the run diverged (a molecule turns beyond the exact rotor's range) at h = " +
                                   schemes::message_number(o.h_fs) + " fs");
        }
        const double V = sys.potential_energy(s), K = sys.kinetic_energy(s), E = V + K;
        if (!std::isfinite(E)) throw std::runtime_error("the run diverged (energy not finite) at h = " + schemes::message_number(o.h_fs) + " fs");
        scale = std::max(scale, std::abs(K) + std::abs(V));
        if (const long done = run * steps + k + 1; o.every > 0 && done % o.every == 0)
          r.trajectory.record(o.h_fs * static_cast<double>(done) / 1000, s.bodies[0], E, V);
        e_sum += E - e_ref;
        e_sq += (E - e_ref) * (E - e_ref);
        v_run += V - v_ref;
        v_sq += (V - v_ref) * (V - v_ref);
        v_sum += V;
        t_sum += temperature_of(K, o.molecules);
        const vec3<double> P = total_momentum(s);
        r.momentum_drift = std::max(r.momentum_drift, std::sqrt((P[0] - P0[0]) * (P[0] - P0[0]) + (P[1] - P0[1]) * (P[1] - P0[1]) + (P[2] - P0[2]) * (P[2] - P0[2])));
      }
      const double n = static_cast<double>(steps);
      // rms from the sums; a variance that is not a number (squares beyond double) stays one
      auto rms = [n](double sq, double sum) {
        const double v = sq / n - (sum / n) * (sum / n);
        return std::isnan(v) ? v : std::sqrt(std::max(0.0, v));
      };
      const double dE = rms(e_sq, e_sum), dV = rms(v_sq, v_run);
      const double ratio = dV > 0 ? 100 * dE / dV : std::nan("");  // no division by zero
      if (!std::isfinite(ratio))
        throw std::runtime_error("run " + std::to_string(run + 1) + ": ΔE/ΔV is not a number (" +
                                 (dV == 0 ? std::string("the potential did not fluctuate") : "the energies' squares are beyond double's range") +
                                 "): the state is not one the scene can measure");
      r.ratio_percent.push_back(ratio);
      r.dE.push_back(dE);
      r.energy_size.push_back(scale);
      if (progress) progress("run " + std::to_string(run + 1) + "/" + std::to_string(o.runs) + ": ΔE/ΔV = " + schemes::message_number(ratio) + " %");
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.steps = steps * o.runs;
    r.ms_per_step = 1000 * seconds / static_cast<double>(r.steps);
    r.cpu_ms_per_step = 1000 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / static_cast<double>(r.steps);
    r.potential_per_molecule = v_sum / static_cast<double>(r.steps) / static_cast<double>(o.molecules);
    r.temperature = t_sum / static_cast<double>(r.steps);
    r.energy_drift_per_ps = (sys.energy(s) - E_begin) / (o.T_ps * o.runs) / static_cast<double>(o.molecules);
    return 0;
  });
  double mean = 0;
  for (double x : r.ratio_percent) mean += x;
  mean /= r.runs;
  double var = 0;
  for (double x : r.ratio_percent) var += (x - mean) * (x - mean);
  r.ratio_mean = mean;
  r.ratio_error = r.runs > 1 ? std::sqrt(var / (r.runs - 1) / r.runs) : std::nan("");  // one run: unknown
  return r;
}

/// g_OO(r) up to 10 Å (bins of 0.05 Å) over `steps` NVE steps of MRDL at h fs from `start`,
/// sampled every `every` steps.
inline std::vector<std::pair<double, double>> sample_oxygen_rdf(const liquid_water_run_options& o, const rigid_bodies_state<double>& start,
                                                                long steps, double h, long every) {
  const auto model = tip3p<double>();
  const auto w = liquid_water_potential(o.molecules, o.density, o.threads);
  oxygen_rdf rdf(10.0, 0.05);
  with_md_integrator(md_integrator_of("MRDL", "Strang-TV", mrdl_rotor_table), nullptr, model.mass, model.moments, w, [&](const auto& method) {
    auto s = start;
    s.forces_current = false;
    std::vector<vec3<double>> x, oxygen(s.bodies.size());
    for (long k = 1; k <= steps; ++k) {
      method.step(s, h);
      if (k % every) continue;
      w.site_positions(s.bodies, x);
      for (std::size_t i = 0; i < oxygen.size(); ++i) oxygen[i] = x[3 * i];
      rdf.add(oxygen, w.options().box);
    }
    return 0;
  });
  return rdf.curve();
}

}  // namespace rotlie::models
