#include "rotlie/runs/spin_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rotlie/runs/binary_estimate.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

std::optional<spin_error_estimate> estimate_spin_error(const spin_setup& setup, const models::mat3<double>& Q, const models::vec3<double>& omega,
                                                       std::string& why, const std::function<bool()>& stop) {
  const int p = setup.method.adaptive ? 0 : setup.method.order;
  if (p == 0 || setup.steps < 2) {
    why = p == 0 ? "an adaptive method meets its tolerance" : "fewer than 2 steps";
    return std::nullopt;
  }
  spin_setup coarse = setup;
  coarse.steps = setup.steps / 2;
  coarse.h = setup.T / static_cast<double>(coarse.steps);
  coarse.every = 0, coarse.error_estimate = false;
  spin_error_estimate e;
  e.order = p, e.step_ratio = coarse.h / setup.h;
  spin_result x;
  try {
    x = spin_run(coarse, stop);
  } catch (const spin_stopped&) {
    throw;
  } catch (const std::runtime_error& failure) {
    why = std::string("its run at twice the step failed: ") + failure.what();
    return std::nullopt;
  }
  e.cpu_s = x.cpu_s;
  const double scale = std::pow(e.step_ratio, p) - 1;
  const models::vec3<double> d{x.omega_body[0] - omega[0], x.omega_body[1] - omega[1], x.omega_body[2] - omega[2]};
  e.attitude_rad = rotation_angle(x.Q, Q) / scale;
  // relative to the spin, or to the mean motion n (ω's unit) for a body turning slower than it
  e.spin_rate_rel = models::norm(d) / std::max(models::norm(omega), 1.0) / scale;
  return e;
}

}  // namespace rotlie::runs
