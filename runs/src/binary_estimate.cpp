#include "rotlie/runs/binary_estimate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <stdexcept>

#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_simulation.hpp"
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

double observed_order(double q, double rho1, double rho2, int declared) {
  const auto ratio = [&](double p) { return (std::pow(rho2, p) - std::pow(rho1, p)) / (std::pow(rho1, p) - 1); };
  double lo = 1, hi = declared;
  if (!(q < ratio(hi))) return hi;
  if (!(q > ratio(lo))) return lo;
  for (int i = 0; i < 60; ++i) (ratio((lo + hi) / 2) < q ? lo : hi) = (lo + hi) / 2;
  return (lo + hi) / 2;
}

namespace {

constexpr double saturation = 0.5;  // a distance (relative, or rad) beyond which two runs are simply apart

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
  std::array<double, 4> est{};
  const auto x2 = setup.steps >= 4 ? companion_end(setup, setup.steps / 2, e.cpu_s, why, stop) : std::nullopt;
  if (x2) {
    // Richardson at ρ1 ≈ 2, each component's order checked by a third run at ρ2 ≈ 4: short of the
    // asymptotic range (a few steps an orbit) the distances shrink slower than 2^p, and dividing by
    // 2^p − 1 would hide most of the error.
    const double rho1 = static_cast<double>(setup.steps) / static_cast<double>(setup.steps / 2);
    const double rho2 = static_cast<double>(setup.steps) / static_cast<double>(setup.steps / 4);
    std::string why4;
    const auto x4 = companion_end(setup, setup.steps / 4, e.cpu_s, why4, stop);
    const auto d1 = distances(*x2, end);
    e.step_ratio = rho1, e.observed_order = p;
    bool saturated = false;
    for (std::size_t c = 0; c < 4; ++c) {
      double pc = p;
      if (x4) {
        const auto d2 = distances(*x4, *x2);
        saturated = saturated || d2[c] > saturation;
        pc = d1[c] > 0 ? observed_order(d2[c] / d1[c], rho1, rho2, p) : p;
      }
      e.observed_order = std::min(e.observed_order, pc);
      est[c] = d1[c] / (std::pow(rho1, pc) - 1);
    }
    // A distance of the orbit's size or a radian says nothing of the order: the run at h/2 then checks
    // it (the runs at h/2, h, 2h), and its distance to the run is the estimate's base.
    std::string why_fine;
    const auto x_fine = saturated ? companion_end(setup, 2 * setup.steps, e.cpu_s, why_fine, stop) : std::nullopt;
    if (x_fine) {
      const auto df = distances(*x_fine, end);
      e.step_ratio = 0.5, e.observed_order = p;
      for (std::size_t c = 0; c < 4; ++c) {
        const double pc = df[c] > 0 ? observed_order(d1[c] / df[c], 2, 4, p) : p;
        e.observed_order = std::min(e.observed_order, pc);
        est[c] = df[c] * std::pow(2, pc) / (std::pow(2, pc) - 1);
      }
    }
  } else {
    // too few steps, or the coarser run failed: the same run at half the step, at the declared order
    std::string why_fine;
    const auto x_fine = companion_end(setup, 2 * setup.steps, e.cpu_s, why_fine, stop);
    if (!x_fine) {
      why = why.empty() ? why_fine : why + "; " + why_fine;
      return std::nullopt;
    }
    why.clear();
    e.step_ratio = 0.5, e.observed_order = p;
    const auto d = distances(*x_fine, end);
    for (std::size_t c = 0; c < 4; ++c) est[c] = d[c] * std::pow(2, p) / (std::pow(2, p) - 1);
  }
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
