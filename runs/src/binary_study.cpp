#include "rotlie/runs/binary_study.hpp"

#include "rotlie/runs/binary_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

namespace {

using models::norm;


// The methods the cost study's goals compare against (Odeint, RK4, the LGVI) are not TV splittings.
bool is_tv_splitting(const std::string& name) { return name.rfind("odeint", 0) != 0 && name != "RK4" && name != "LGVI"; }

binary_setup setup_named(const std::string& system, int order, const std::string& integrator, double h, double T) {
  binary_request r;
  r.system = system;
  r.order = std::to_string(order);
  r.integrator = integrator;
  r.h = schemes::message_number(h);
  r.T = schemes::message_number(T);
  r.no_error_estimate = true;  // the study measures errors against a reference of its own
  return binary_setup_of(r);
}

}  // namespace

double binary_state_error(const models::binary_state<double>& x, const models::binary_state<double>& ref) {
  double e = models::norm(models::vec3<double>{x.r[0] - ref.r[0], x.r[1] - ref.r[1], x.r[2] - ref.r[2]}) / norm(ref.r);
  for (int b = 0; b < 2; ++b) e = std::max(e, rotation_angle(x.body[b].Q, ref.body[b].Q));
  return e;
}

binary_observables observe_binary(binary_setup setup, long every) {
  setup.every = std::max(1L, every);
  setup.error_estimate = false;
  binary_observer observer;
  const auto result = binary_run(setup, [&](const binary_sample& s) { observer.add(s.t, s.x); });
  return observer.result(setup.system_model(), result.end.x);
}

binary_setup with_impulse(binary_setup setup, double dv) {
  auto& v = setup.start.v;
  const double speed = norm(v);
  for (auto& c : v) c *= (speed - dv) / speed;
  return setup;
}

binary_cost_result binary_cost_study(const binary_cost_plan& plan, const std::function<void(const std::string&)>& progress) {
  binary_cost_result out;
  for (const int order : plan.orders) {
    if (progress) progress("Binary asteroid: the reference at order " + std::to_string(order));
    const auto reference = binary_run(setup_named(plan.system, order, plan.reference, plan.reference_h, plan.T));
    const auto check = binary_run(setup_named(plan.system, order, plan.reference, plan.reference_h / 2, plan.T));
    out.reference_error.push_back(binary_state_error(reference.end.x, check.end.x));
    const auto add = [&](const std::string& name, double h) {
      if (progress) progress("Binary asteroid: " + name + " at order " + std::to_string(order) + ", h = " + schemes::message_number(h) + " s");
      binary_cost_row row{name, order, h};
      try {
        const auto r = binary_run(setup_named(plan.system, order, name, h, plan.T));
        row.steps = r.setup.steps, row.evaluations = r.evaluations, row.cpu_s = r.cpu_s;
        row.error = binary_state_error(r.end.x, reference.end.x);
        row.energy_error = r.check.max_rel_energy_error, row.angular_momentum_error = r.check.max_rel_angular_momentum_error;
        row.unstable = r.check.unstable;
      } catch (const std::exception&) {
        row.unstable = true, row.error = std::numeric_limits<double>::infinity();
      }
      out.rows.push_back(row);
    };
    for (const auto& name : plan.integrators)
      for (const double h : plan.steps) add(name, h);
    for (const auto& name : plan.adaptive) add(name, plan.adaptive_h);
  }
  return out;
}

std::optional<cheapest_splitting> cheapest_splitting_at(const binary_cost_result& result, int order, const std::string& anchor, double h) {
  const auto& rows = result.rows;
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const binary_cost_row& r) { return r.order == order && r.integrator == anchor && r.h == h; });
  if (it == rows.end()) return std::nullopt;
  cheapest_splitting out;
  out.anchor = *it;
  const binary_cost_row* best = nullptr;
  for (const auto& r : rows)
    if (r.order == order && is_tv_splitting(r.integrator) && r.error <= it->error && !r.unstable && (!best || r.cpu_s < best->cpu_s)) best = &r;
  if (!best) return out;
  out.found = true;
  out.best = *best;
  out.less_cpu = it->cpu_s >= best->cpu_s;
  out.cpu_ratio = out.less_cpu ? it->cpu_s / best->cpu_s : best->cpu_s / it->cpu_s;
  return out;
}

}  // namespace rotlie::runs
