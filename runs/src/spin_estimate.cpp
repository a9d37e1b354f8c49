#include "rotlie/runs/spin_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "rotlie/runs/binary_estimate.hpp"
#include "rotlie/runs/richardson.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

namespace {

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
  const auto run = [&](long steps, std::string& failed) { return spin_companion(setup, steps, e.cpu_s, failed, stop); };
  const auto distance = [](const spin_result& a, const spin_result& b) { return spin_distances(a.Q, a.omega_body, b.Q, b.omega_body); };
  spin_result end;
  end.Q = Q, end.omega_body = omega;
  const auto r = estimate_by_companions<2>(setup.steps, p, end, run, distance, why);
  if (!r) return std::nullopt;
  const auto& est = r->error;
  e.observed_order = r->observed_order, e.step_ratio = r->step_ratio;
  e.attitude_rad = est[0], e.spin_rate_rel = est[1];
  return e;
}

}  // namespace rotlie::runs
