#pragma once
// vZS section V.A: the orientation error of an integrator on the free water molecule,
//   δ(t) = ⟨Tr[(A − A_ex)(A − A_ex)ᵀ]/6⟩^{1/2}   (A = Qᵀ; the trace is the squared Frobenius distance),
// averaged over a canonical ensemble, against the exact flow from each run's own initial state, and
// the "10 % error time" τ of δ ≈ t/(10τ), fitted by least squares through the origin over the
// samples with δ ≤ 0.1 (the paper's "moderate t"; beyond, δ saturates towards 1).
//
// The reference is exact_free_body in float128 for the body the run integrates (its moments and
// initial state as held in the run's scalar, converted exactly), so that a double run is compared
// with the exact motion of the same double body: SIER2's δ then measures its round-off alone. The
// reference's own estimated error is kept beside δ; a sample within a factor 10 of it is left out
// of the fit (reference_margin).

#include <cmath>
#include <vector>

#include "rotlie/models/error_protocol.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/models/scenes/free_water.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::models {

/// The command line's defaults: the samples of δ stay below 10 % for MRDL at 8 fs (τ ≈ 7.6 ps in
/// the paper) only if the run is short; the ensemble is large enough for a τ to a few percent.
inline constexpr double free_water_default_T_ps = 5;
inline constexpr long free_water_default_runs = 100;

struct free_water_result : md_ensemble_cost {
  std::vector<double> t_ps;     ///< sample times
  std::vector<double> delta;    ///< ensemble δ at each sample
  std::vector<double> reference_delta;  ///< the exact reference's own estimated δ there
  double tau_ps = std::nan("");  ///< fitted; NaN when fewer than two samples qualify
  double tau_error_ps = std::nan("");  ///< jackknife standard error of tau over the runs
  int fitted_samples = 0;
  std::vector<std::vector<double>> run_d2;  ///< per run, Tr[(A − A_ex)(A − A_ex)ᵀ]/6 at each sample
  bool finite = true;           ///< every sampled attitude finite
};

/// Least squares of δ = a t through the origin over the samples that qualify; τ = 1/(10 a).
inline double fitted_tau(const std::vector<double>& t, const std::vector<double>& delta, const std::vector<double>& reference,
                         int* fitted = nullptr) {
  double st = 0, stt = 0;
  int n = 0;
  for (std::size_t j = 0; j < t.size(); ++j) {
    if (!(delta[j] <= 0.1) || !(delta[j] > reference_margin * reference[j])) continue;
    st += t[j] * delta[j];
    stt += t[j] * t[j];
    ++n;
  }
  if (fitted) *fitted = n;
  return n >= 2 && st > 0 ? stt / (10 * st) : std::nan("");
}

/// τ from the ensemble, and its jackknife error (τ refitted with each run left out in turn).
inline void fit_tau(free_water_result& r) {
  r.tau_ps = fitted_tau(r.t_ps, r.delta, r.reference_delta, &r.fitted_samples);
  const std::size_t n = r.run_d2.size();
  if (n < 2 || !std::isfinite(r.tau_ps)) return;
  std::vector<double> total(r.t_ps.size(), 0.0), d(r.t_ps.size());
  for (const auto& run : r.run_d2)
    for (std::size_t j = 0; j < total.size(); ++j) total[j] += run[j];
  std::vector<double> taus;
  for (const auto& run : r.run_d2) {
    for (std::size_t j = 0; j < d.size(); ++j) d[j] = std::sqrt(std::max(0.0, total[j] - run[j]) / static_cast<double>(n - 1));
    taus.push_back(fitted_tau(r.t_ps, d, r.reference_delta));
  }
  double mean = 0, ss = 0;
  for (double x : taus) mean += x;
  mean /= static_cast<double>(n);
  for (double x : taus) ss += (x - mean) * (x - mean);
  r.tau_error_ps = std::sqrt(ss * static_cast<double>(n - 1) / static_cast<double>(n));
}

/// `samples` sample times evenly spread over the run (each a whole step).
template <class T>
free_water_result run_free_water(const free_water<T>& scene, const md_run_options& o, int samples = 32) {
  const long steps = md_steps(o);
  const long K = std::min<long>(samples, steps);
  std::vector<long> at(static_cast<std::size_t>(K));
  for (long j = 1; j <= K; ++j) at[static_cast<std::size_t>(j - 1)] = (j * steps + K - 1) / K;
  std::vector<double> sum2(at.size(), 0.0), ref2(at.size(), 0.0);
  const vec3<quad> Iq{quad(scene.moments[0]), quad(scene.moments[1]), quad(scene.moments[2])};

  return with_scene_integrator<T>(scene, o, [&](const auto& method) {
    free_water_result r;
    const T h = T(o.h_fs);
    run_ensemble(scene, o, method, steps, r, [&](rigid_bodies_state<T>& x, auto& step) {
      body_state<quad> start;
      for (std::size_t i = 0; i < 9; ++i) start.Q.a[i] = quad(x.bodies[0].rot.Q.a[i]);
      for (std::size_t i = 0; i < 3; ++i) start.G[i] = quad(x.bodies[0].rot.G[i]);
      const exact_free_body<quad> exact(Iq, start);
      std::vector<mat3<quad>> Qex(at.size());
      for (std::size_t j = 0; j < at.size(); ++j) {
        const auto e = exact.evaluate(quad(h) * quad(at[j]));
        Qex[j] = e.state.Q;
        ref2[j] += 1.5 * static_cast<double>(e.error_estimate * e.error_estimate);  // 9 entries / 6
      }
      std::size_t next = 0;
      r.run_d2.emplace_back(at.size(), 0.0);
      auto observe = [&](long k, const T&, const rigid_bodies_state<T>& s) {
        if (next >= at.size() || k != at[next]) return true;
        quad d2 = 0;
        for (std::size_t i = 0; i < 9; ++i) {
          const quad d = quad(s.bodies[0].rot.Q.a[i]) - Qex[next].a[i];
          d2 += d * d;
        }
        const double v = static_cast<double>(d2) / 6;
        if (!std::isfinite(v)) r.finite = false;
        r.run_d2.back()[next] = v;
        sum2[next++] += v;
        return r.finite;
      };
      step(x, observe);
      return r.finite;  // a non-finite attitude ends the ensemble
    });
    const double n = static_cast<double>(o.runs);
    for (std::size_t j = 0; j < at.size(); ++j) {
      r.t_ps.push_back(o.h_fs * static_cast<double>(at[j]) / 1000);
      r.delta.push_back(r.finite ? std::sqrt(sum2[j] / n) : std::nan(""));
      r.reference_delta.push_back(std::sqrt(ref2[j] / n));
    }
    fit_tau(r);
    return r;
  });
}

}  // namespace rotlie::models
