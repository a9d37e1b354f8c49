#pragma once
// vZS section V.B, Table I: conservation of H and L_z for the water dipole in a field. Per run,
//   ΔH/ΔV = rms(H − ⟨H⟩) / rms(V − ⟨V⟩)  (in %: the energy error on the natural scale of the
//            potential's own fluctuation),
//   ΔL_z/⟨L_z⟩ = rms(L_z − ⟨L_z⟩) / |⟨L_z⟩|,
// over every state of the run (the start and each step); then mean ± standard error over the
// ensemble. L_z is the molecule's spin about its centre, (Q G)_z: the field's torque is
// perpendicular to z, and the orbital q × p of the drifting molecule is a constant whose computed
// value would only add the round-off of a growing q to the spin's.
//
// Fluctuations of 10⁻¹³ relative are measured without cancellation: every quantity is accumulated
// as its difference from its value at the start (exact for nearby numbers), in the run's scalar.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/models/scenes/dipole_field.hpp"

namespace rotlie::models {

/// The command line's defaults (chosen so that the error bars are like the paper's; see the report).
inline constexpr double dipole_field_default_T_ps = 100;
inline constexpr long dipole_field_default_runs = 50;

struct dipole_field_result : md_ensemble_cost {
  std::vector<double> dH_over_dV_percent, dLz_over_Lz;  ///< per finished run
  mean_error dH, dLz;                                   ///< over the ensemble
  long failed_runs = 0;                                 ///< runs that went non-finite (stopped there)
  /// runs that stayed finite but whose ΔH/ΔV or ΔL_z/⟨L_z⟩ is not a number: V did not fluctuate
  /// (ΔV = 0), or the squares of the fluctuations are beyond the scalar's range; left out of the means
  long undefined_runs = 0;
  /// min over the runs of |ω|·h/ε at the start: the angle one step turns the molecule, in units of
  /// the scalar's round-off (below about 1000 the step's change is lost in round-off)
  double turn_per_step = std::numeric_limits<double>::infinity();
};

namespace detail {
/// rms of x − ⟨x⟩ from sums of d = x − x₀ (Σd, Σd², n).
template <class T>
T shifted_rms(const T& sum, const T& sum2, long n) {
  using std::sqrt;
  const T m = sum / T(n);
  const T v = sum2 / T(n) - m * m;
  using std::isnan;
  if (isnan(v)) return v;  // squares beyond the scalar's range: not a number, never 0
  return v > 0 ? sqrt(v) : T(0);
}
}  // namespace detail

template <class T>
dipole_field_result run_dipole_field(const dipole_field<T>& scene, const md_run_options& o) {
  const long steps = md_steps(o);
  return with_scene_integrator<T>(scene, o, [&](const auto& method) {
    const auto& sys = method.system();
    dipole_field_result r;
    run_ensemble(scene, o, method, steps, r, [&](rigid_bodies_state<T>& x, auto& step) {
      sys.ensure_forces(x);  // V at the start (the first kick would evaluate it anyway)
      auto lz = [](const rigid_bodies_state<T>& s) { return lab_spin(s.bodies[0])[2]; };
      const T H0 = sys.kinetic_energy(x) + x.potential, V0 = x.potential, L0 = lz(x);
      {
        using std::sqrt;
        const auto& G = x.bodies[0].rot.G;
        T w2 = 0;
        for (std::size_t i = 0; i < 3; ++i) w2 += (G[i] / scene.moments[i]) * (G[i] / scene.moments[i]);
        r.turn_per_step = std::min(r.turn_per_step, static_cast<double>(sqrt(w2) * T(o.h_fs) / std::numeric_limits<T>::epsilon()));
      }
      T sH = 0, sH2 = 0, sV = 0, sV2 = 0, sL = 0, sL2 = 0, lsum = 0;
      long n = 0;
      bool finite = true;
      auto observe = [&](long, const T&, const rigid_bodies_state<T>& s) {
        const T V = s.potential, dH = sys.kinetic_energy(s) + V - H0, dV = V - V0, L = lz(s), dL = L - L0;
        sH += dH, sH2 += dH * dH, sV += dV, sV2 += dV * dV, sL += dL, sL2 += dL * dL, lsum += L;
        ++n;
        using std::isfinite;
        finite = isfinite(static_cast<double>(dH)) && isfinite(static_cast<double>(dL));
        return finite;
      };
      observe(0, T(0), x);
      step(x, observe);
      if (!finite) {
        ++r.failed_runs;
      } else {
        const T dH = detail::shifted_rms(sH, sH2, n), dV = detail::shifted_rms(sV, sV2, n);
        const T dL = detail::shifted_rms(sL, sL2, n);
        using std::abs;
        // no division by zero: V that did not fluctuate, or a zero mean L_z, gives no number
        const T mean_L = abs(lsum / T(n));
        const double ratio = dV > 0 ? static_cast<double>(100 * dH / dV) : std::nan("");
        const double lz_ratio = mean_L > 0 ? static_cast<double>(dL / mean_L) : std::nan("");
        if (!std::isfinite(ratio) || !std::isfinite(lz_ratio)) {
          ++r.undefined_runs;
        } else {
          r.dH_over_dV_percent.push_back(ratio);
          r.dLz_over_Lz.push_back(lz_ratio);

        }
      }
      return true;  // a failed run is counted, and the ensemble goes on
    });
    r.dH = ensemble_mean(r.dH_over_dV_percent);
    r.dLz = ensemble_mean(r.dLz_over_Lz);
    return r;
  });
}

}  // namespace rotlie::models
