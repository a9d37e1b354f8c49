#include "rotlie/runs/binary_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <stdexcept>

#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_simulation.hpp"
#include "rotlie/runs/richardson.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {

namespace {

// The composition's declared order: its TV table's, or its rotor table's when lower.
int declared_order(const binary_method& m) {
  switch (m.family) {
    case binary_method::kind::rk4:
      return 4;
    case binary_method::kind::lgvi:
      return 2;
    case binary_method::kind::odeint:
      return 0;
    case binary_method::kind::splitting:
      break;
  }
  int p = schemes::reference_scheme(m.splitting.tv_table)->order;
  for (const auto& rotor : m.rotor)
    if (rotor) p = std::min(p, rotor->order);
  return p;
}

double distance(const models::vec3<double>& a, const models::vec3<double>& b) {
  return models::norm(models::vec3<double>{a[0] - b[0], a[1] - b[1], a[2] - b[2]});
}

}  // namespace

double rotation_angle(const models::mat3<double>& A, const models::mat3<double>& B) {
  const auto R = transpose(A) * B;
  const double c = (R(0, 0) + R(1, 1) + R(2, 2) - 1) / 2;
  const double s = std::sqrt((R(2, 1) - R(1, 2)) * (R(2, 1) - R(1, 2)) + (R(0, 2) - R(2, 0)) * (R(0, 2) - R(2, 0)) + (R(1, 0) - R(0, 1)) * (R(1, 0) - R(0, 1))) / 2;
  return std::atan2(s, c);
}

namespace {

// The final state of the setup's run in `steps` steps (nothing when it touched or failed: `why` says so).
std::optional<models::binary_state<double>> companion_end(const binary_setup& setup, long steps, double& cpu_s, std::string& why,
                                                          const std::function<bool()>& stop) {
  binary_setup c = setup;
  c.steps = steps, c.h = setup.T / static_cast<double>(steps);
  c.every = 0, c.observe = false, c.error_estimate = false;
  const std::string which = "its run at " + std::to_string(setup.steps) + "/" + std::to_string(steps) + " of the step";
  try {
    binary_simulation companion(c);
    companion.advance(steps, {}, {}, stop);
    if (companion.steps() < steps) throw binary_stopped();
    cpu_s += companion.result().cpu_s;
    return companion.state();
  } catch (const binary_contact&) {
    why = which + " touched";
  } catch (const binary_stopped&) {
    throw;
  } catch (const std::runtime_error& failure) {
    why = which + " failed (" + failure.what() + ")";
  }
  return std::nullopt;
}

// The four distances between two final states: position and velocity relative to `end`'s, attitudes.
std::array<double, 4> distances(const models::binary_state<double>& x, const models::binary_state<double>& end) {
  return {distance(x.r, end.r) / models::norm(end.r), distance(x.v, end.v) / models::norm(end.v), rotation_angle(x.body[0].Q, end.body[0].Q),
          rotation_angle(x.body[1].Q, end.body[1].Q)};
}

}  // namespace

std::optional<binary_error_estimate> estimate_binary_error(const binary_setup& setup, const models::binary_state<double>& end, std::string& why,
                                                           const std::function<bool()>& stop) {
  const int p = declared_order(setup.method);
  if (p == 0 || setup.steps < 1) {
    why = p == 0 ? "an adaptive method meets its tolerance" : "no step was taken";
    return std::nullopt;
  }
  binary_error_estimate e;
  e.order = p;
  const auto run = [&](long steps, std::string& failed) { return companion_end(setup, steps, e.cpu_s, failed, stop); };
  const auto r = estimate_by_companions<4>(setup.steps, p, end, run, distances, why);
  if (!r) return std::nullopt;
  const auto& est = r->error;
  e.observed_order = r->observed_order, e.step_ratio = r->step_ratio;
  e.position_rel = est[0], e.velocity_rel = est[1], e.attitude1_rad = est[2], e.attitude2_rad = est[3];
  return e;
}

std::optional<binary_error_estimate> estimate_contact_error(const binary_setup& setup, long step, const models::binary_state<double>& touching,
                                                            std::string& why, const std::function<bool()>& stop) {
  const int p = declared_order(setup.method);
  binary_setup fine = setup;
  fine.steps = 2 * step, fine.h = setup.h / 2, fine.T = fine.h * static_cast<double>(fine.steps);
  fine.every = 0, fine.observe = false, fine.error_estimate = false, fine.stops_at_contact = false;
  binary_error_estimate e;
  e.order = p, e.step_ratio = 0.5;
  models::binary_state<double> x;
  try {
    binary_simulation companion(fine);
    companion.advance(fine.steps, {}, {}, stop);
    if (companion.steps() < fine.steps) throw binary_stopped();
    x = companion.state();
    e.cpu_s = companion.result().cpu_s;
  } catch (const binary_stopped&) {
    throw;
  } catch (const std::runtime_error& failure) {
    why = std::string("failed: ") + failure.what();
    return std::nullopt;
  }
  const double scale = 1 - std::pow(0.5, p);  // x_h − x_{h/2} ≈ (1 − 2^−p) times the error at h
  e.position_rel = distance(x.r, touching.r) / models::norm(touching.r) / scale;
  e.velocity_rel = distance(x.v, touching.v) / models::norm(touching.v) / scale;
  e.attitude1_rad = rotation_angle(x.body[0].Q, touching.body[0].Q) / scale;
  e.attitude2_rad = rotation_angle(x.body[1].Q, touching.body[1].Q) / scale;
  if (!(std::isfinite(e.position_rel) && std::isfinite(e.attitude1_rad) && std::isfinite(e.attitude2_rad))) {
    why = "ends with values that are not finite";
    return std::nullopt;
  }
  return e;
}

}  // namespace rotlie::runs
