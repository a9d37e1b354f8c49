#include "rotlie/runs/spin_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "rotlie/runs/binary_estimate.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

namespace {

constexpr double spin_saturation = 0.5;  // a distance (rad, or relative) beyond which two runs are simply apart

// The final attitude and body-frame angular velocity of the setup's run in `steps` steps, or nothing
// (it failed: `why` says so).
std::optional<spin_result> spin_companion(const spin_setup& setup, long steps, double& cpu_s, std::string& why, const std::function<bool()>& stop) {
  spin_setup c = setup;
  c.steps = steps, c.h = setup.T / static_cast<double>(steps);
  c.every = 0, c.error_estimate = false;
  try {
    auto x = spin_run(c, stop);
    cpu_s += x.cpu_s;
    return x;
  } catch (const spin_stopped&) {
    throw;
  } catch (const std::runtime_error& failure) {
    why = "its run at " + std::to_string(setup.steps) + "/" + std::to_string(steps) + " of the step failed (" + failure.what() + ")";
  }
  return std::nullopt;
}

// The attitude's angle and the spin rate's relative distance (to the spin, or to the mean motion n, ω's
// unit, for a body turning slower than it).
std::array<double, 2> spin_distances(const models::mat3<double>& Qa, const models::vec3<double>& wa, const models::mat3<double>& Q,
                                     const models::vec3<double>& omega) {
  const models::vec3<double> d{wa[0] - omega[0], wa[1] - omega[1], wa[2] - omega[2]};
  return {rotation_angle(Qa, Q), models::norm(d) / std::max(models::norm(omega), 1.0)};
}

}  // namespace

std::optional<spin_error_estimate> estimate_spin_error(const spin_setup& setup, const models::mat3<double>& Q, const models::vec3<double>& omega,
                                                       std::string& why, const std::function<bool()>& stop) {
  const int p = setup.method.adaptive ? 0 : setup.method.order;
  if (p == 0 || setup.steps < 1) {
    why = p == 0 ? "an adaptive method meets its tolerance" : "no step was taken";
    return std::nullopt;
  }
  spin_error_estimate e;
  e.order = p;
  std::array<double, 2> est{};
  const auto x2 = setup.steps >= 4 ? spin_companion(setup, setup.steps / 2, e.cpu_s, why, stop) : std::nullopt;
  std::optional<spin_result> x_fine;
  if (x2) {
    // Richardson at ρ1 ≈ 2, the order checked by a third run at ρ2 ≈ 4 (binary_estimate.hpp): short of the
    // asymptotic range the distances shrink slower than 2^p
    const double rho1 = static_cast<double>(setup.steps) / static_cast<double>(setup.steps / 2);
    const double rho2 = static_cast<double>(setup.steps) / static_cast<double>(setup.steps / 4);
    std::string why4;
    const auto x4 = spin_companion(setup, setup.steps / 4, e.cpu_s, why4, stop);
    const auto d1 = spin_distances(x2->Q, x2->omega_body, Q, omega);
    e.step_ratio = rho1, e.observed_order = p;
    bool saturated = false;
    for (std::size_t c = 0; c < 2; ++c) {
      double pc = p;
      if (x4) {
        const auto d2 = spin_distances(x4->Q, x4->omega_body, x2->Q, x2->omega_body);
        saturated = saturated || d2[c] > spin_saturation;
        pc = d1[c] > 0 ? observed_order(d2[c] / d1[c], rho1, rho2, p) : p;
      }
      e.observed_order = std::min(e.observed_order, pc);
      est[c] = d1[c] / (std::pow(rho1, pc) - 1);
    }
    // a run at 4h a radian away says nothing of the order: the run at h/2 checks it instead
    std::string why_fine;
    if (saturated) x_fine = spin_companion(setup, 2 * setup.steps, e.cpu_s, why_fine, stop);
    if (x_fine) {
      const auto df = spin_distances(x_fine->Q, x_fine->omega_body, Q, omega);
      e.step_ratio = 0.5, e.observed_order = p;
      for (std::size_t c = 0; c < 2; ++c) {
        const double pc = df[c] > 0 ? observed_order(d1[c] / df[c], 2, 4, p) : p;
        e.observed_order = std::min(e.observed_order, pc);
        est[c] = df[c] * std::pow(2, pc) / (std::pow(2, pc) - 1);
      }
    }
  } else {
    // too few steps, or the coarser run failed: the run at half the step, at the declared order
    std::string why_fine;
    x_fine = spin_companion(setup, 2 * setup.steps, e.cpu_s, why_fine, stop);
    if (!x_fine) {
      why = why.empty() ? why_fine : why + "; " + why_fine;
      return std::nullopt;
    }
    why.clear();
    e.step_ratio = 0.5, e.observed_order = p;
    const auto d = spin_distances(x_fine->Q, x_fine->omega_body, Q, omega);
    for (std::size_t c = 0; c < 2; ++c) est[c] = d[c] * std::pow(2, p) / (std::pow(2, p) - 1);
  }
  e.attitude_rad = est[0], e.spin_rate_rel = est[1];
  return e;
}

}  // namespace rotlie::runs
