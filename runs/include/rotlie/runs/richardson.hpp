#pragma once
// The error of a fixed-step run's final state from companion runs of the same method (Richardson), for
// any scene: binary_estimate.hpp and spin_estimate.hpp give it their runs and their distances. Two runs at
// steps h and ρh end apart by about (ρ^p − 1) times the error at h; short of the asymptotic range (a few
// steps an orbit) the distances shrink slower than the declared order p says, and dividing by 2^p − 1
// would hide most of the error. So each component's order is checked by a third run at about 4h; when
// the run at 4h ends a radian or half an orbit away it says nothing of the order, and a run at h/2 checks
// it instead (the runs at h/2, h, 2h; its distance to the run is then the base). Runs of fewer than 4
// steps, or whose run at 2h fails, take the run at h/2 alone at the declared order.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace rotlie::runs {

/// The order three runs of one method show: the p in [1, declared] for which (ρ2^p − ρ1^p)/(ρ1^p − 1) = q,
/// q the ratio of the distances (ρ2h, ρ1h) and (ρ1h, h) of their final states (the ratio grows with p;
/// it is 2^p at ρ1 = 2, ρ2 = 4).
inline double observed_order(double q, double rho1, double rho2, int declared) {
  const auto ratio = [&](double p) { return (std::pow(rho2, p) - std::pow(rho1, p)) / (std::pow(rho1, p) - 1); };
  double lo = 1, hi = declared;
  if (!(q < ratio(hi))) return hi;
  if (!(q > ratio(lo))) return lo;
  for (int i = 0; i < 60; ++i) (ratio((lo + hi) / 2) < q ? lo : hi) = (lo + hi) / 2;
  return (lo + hi) / 2;
}

/// A distance (relative, or rad) beyond which two runs are simply apart: it says nothing of the order.
inline constexpr double richardson_saturation = 0.5;

template <std::size_t N>
struct richardson_estimate {
  std::array<double, N> error{};  ///< each component's estimated error at h
  double observed_order = 0;      ///< the lowest over the components, in [1, p]
  double step_ratio = 0;          ///< ρ of the companion the estimate divides by (0.5: the run at h/2)
};

/// The estimate for a run of `steps` steps of a method of order p that ended at `end`. `run(k, why)`
/// is the same run in k steps (its end, or nothing with `why` set); `distance(a, b)` the N distances of
/// two ends. Nothing when the companions failed (`why` says which).
template <std::size_t N, class State, class Run, class Distance>
std::optional<richardson_estimate<N>> estimate_by_companions(long steps, int p, const State& end, Run&& run, Distance&& distance, std::string& why) {
  richardson_estimate<N> e;
  const double P = std::pow(2.0, p);
  const auto x2 = steps >= 4 ? run(steps / 2, why) : std::nullopt;
  if (!x2) {
    std::string why_fine;
    const auto x_fine = run(2 * steps, why_fine);
    if (!x_fine) {
      why = why.empty() ? why_fine : why + "; " + why_fine;
      return std::nullopt;
    }
    why.clear();
    e.step_ratio = 0.5, e.observed_order = p;
    const auto d = distance(*x_fine, end);
    for (std::size_t c = 0; c < N; ++c) e.error[c] = d[c] * P / (P - 1);
    return e;
  }
  const double rho1 = static_cast<double>(steps) / static_cast<double>(steps / 2);
  const double rho2 = static_cast<double>(steps) / static_cast<double>(steps / 4);
  std::string why4;
  const auto x4 = run(steps / 4, why4);
  const auto d1 = distance(*x2, end);
  std::array<double, N> d2{};
  if (x4) d2 = distance(*x4, *x2);
  const bool saturated = x4 && std::any_of(d2.begin(), d2.end(), [](double d) { return d > richardson_saturation; });
  std::string why_fine;
  const auto x_fine = saturated ? run(2 * steps, why_fine) : std::nullopt;
  const auto df = x_fine ? distance(*x_fine, end) : std::array<double, N>{};
  e.step_ratio = x_fine ? 0.5 : rho1, e.observed_order = p;
  for (std::size_t c = 0; c < N; ++c) {
    if (x_fine) {  // the runs at h/2, h, 2h
      const double pc = df[c] > 0 ? observed_order(d1[c] / df[c], 2, 4, p) : p;
      e.observed_order = std::min(e.observed_order, pc);
      e.error[c] = df[c] * std::pow(2.0, pc) / (std::pow(2.0, pc) - 1);
    } else {  // the runs at h, ρ1h, ρ2h
      const double pc = x4 && d1[c] > 0 ? observed_order(d2[c] / d1[c], rho1, rho2, p) : p;
      e.observed_order = std::min(e.observed_order, pc);
      e.error[c] = d1[c] / (std::pow(rho1, pc) - 1);
    }
  }
  return e;
}

}  // namespace rotlie::runs
