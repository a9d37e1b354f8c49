#include "rotlie/runs/didymos_study.hpp"

#include <cmath>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

binary_setup didymos_setup(int order, const std::string& integrator, double h, double T, bool gubas_start) {
  binary_request r;
  r.system = "didymos";
  r.order = std::to_string(order);
  r.integrator = integrator;
  r.h = schemes::message_number(h);
  r.T = schemes::message_number(T);
  r.no_error_estimate = true;  // the studies measure errors against references of their own
  if (gubas_start) {
    // the GUBAS example's start (example/hou_config.cfg)
    r.state_text = R"({"r": [1.2, 0, 0], "v": [0, 0.000175704287113523, 0], "Q1": [[1,0,0],[0,1,0],[0,0,1]], "Q2": [[1,0,0],[0,1,0],[0,0,1]],
                       "omega1": [0, 0, 7.72269580528e-4], "omega2": [0, 0, 1.46420239261e-4]})";
  }
  return binary_setup_of(r);
}

double didymos_span_s(double days) { return std::round(days * 86400 / 60) * 60; }

std::vector<didymos_benchmark_row> didymos_benchmark(double T) {
  std::vector<didymos_benchmark_row> rows;
  for (const bool gubas : {false, true})
    for (const int order : {2, 4, 6, 8}) rows.push_back({gubas, order, observe_binary(didymos_setup(order, "KEPLER4", 60, T, gubas), 5)});
  return rows;
}

dart_result dart_period_change(const dart_impact& impact, double T) {
  const auto before_setup = didymos_setup(4, "KEPLER4", 60, T, false);
  dart_result out;
  out.secondary_mass_kg = before_setup.system_model().body(1).mass;
  out.dv_km_s = impact.beta * impact.mass_kg * impact.speed_km_s / out.secondary_mass_kg;
  out.period_before_h = observe_binary(before_setup, 5).orbit_period_h;
  for (const double dv : {out.dv_km_s, out.dv_km_s / 2, 2 * out.dv_km_s}) {
    const double after = observe_binary(with_impulse(before_setup, dv), 5).orbit_period_h;
    out.rows.push_back({dv, after, (after - out.period_before_h) * 60});
  }
  return out;
}

dart_beta_result dart_beta_sweep(const dart_impact& impact, const std::vector<double>& betas, double tilted_beta, double tilt_deg,
                                 double target_min, double T) {
  const auto before_setup = didymos_setup(4, "KEPLER4", 60, T, false);
  dart_beta_result out;
  out.secondary_mass_kg = before_setup.system_model().body(1).mass;
  out.period_before_h = observe_binary(before_setup, 5).orbit_period_h;
  out.target_min = target_min;
  const auto push = [&](double beta, double tilt_deg_here) {
    auto setup = before_setup;
    const double dv = beta * impact.mass_kg * impact.speed_km_s / out.secondary_mass_kg;
    // against the motion, turned by the tilt about the line of centres (out of the orbit plane)
    const auto& v = setup.start.v;
    const double speed = models::norm(v), tilt = tilt_deg_here * std::acos(-1.0) / 180;
    const auto& r = setup.start.r;
    const models::vec3<double> normal = models::cross(r, v);
    const double n = models::norm(normal);
    for (std::size_t k = 0; k < 3; ++k) setup.start.v[k] -= dv * (std::cos(tilt) * v[k] / speed + std::sin(tilt) * normal[k] / n);
    const auto seen = observe_binary(setup, 5);
    dart_beta_row row;
    row.beta = beta, row.dv_km_s = dv, row.tilt_deg = tilt_deg_here;
    row.change_min = (seen.orbit_period_h - out.period_before_h) * 60;
    row.libration_amplitude_deg = seen.libration_amplitude_deg;
    row.npa_angle_max_deg = seen.rotation[1].npa_angle_max_deg;
    row.tumbling = seen.rotation[1].tumbling;
    out.rows.push_back(row);
  };
  for (const double beta : betas) push(beta, 0);
  for (std::size_t k = 1; k < out.rows.size(); ++k) {
    const auto &a = out.rows[k - 1], &b = out.rows[k];
    if ((a.change_min - target_min) * (b.change_min - target_min) <= 0 && a.change_min != b.change_min)
      out.beta_for_target = a.beta + (target_min - a.change_min) / (b.change_min - a.change_min) * (b.beta - a.beta);
  }
  push(tilted_beta, tilt_deg);
  return out;
}

binary_cost_plan didymos_cost_plan(double orbits, bool quick) {
  binary_cost_plan plan;
  plan.T = orbits * didymos_orbit_unit_s;
  plan.integrators = {"SIER2", "SIER4", "SIER6", "KEPLER2", "KEPLER4", "KEPLER6", "SIER4/ABCBA2:ABC", "KEPLER4/ABCBA2:ABC", "KEPLER6/ABCBA2:ABC",
                      "LGVI", "RK4"};
  plan.steps = quick ? std::vector<double>{480, 120, 30} : std::vector<double>{480, 240, 120, 60, 30};
  plan.adaptive = {"odeint-rkf78:1e-9", "odeint-rkf78:1e-11", "odeint-rkf78:1e-13"};
  plan.adaptive_h = 480;
  plan.reference = "KEPLER4";
  plan.reference_h = 7.5;
  return plan;
}

std::vector<term_effect> didymos_term_effects(double T) {
  std::vector<term_effect> out;
  const auto without = binary_run(didymos_setup(4, "KEPLER4", 60, T, false));
  for (const auto& term : binary_terms()) {
    if (term.example.empty()) continue;
    binary_request r;
    r.system = "didymos", r.order = "4", r.integrator = "KEPLER4", r.h = "60", r.T = schemes::message_number(T), r.no_error_estimate = true;
    r.terms[term.name] = term.example;
    const auto with = binary_run(binary_setup_of(r));
    term_effect e;
    e.name = term.name, e.values = term.example;
    const auto& a = with.end.x.r;
    const auto& b = without.end.x.r;
    e.separation_change_km = models::norm(models::vec3<double>{a[0] - b[0], a[1] - b[1], a[2] - b[2]});
    e.phase_change_deg = (std::atan2(a[1], a[0]) - std::atan2(b[1], b[0])) * 180 / std::acos(-1.0);
    for (const auto& [name, t] : with.setup.terms)
      if (name == term.name) e.values_at_end = t->values(with.end.x, with.end.t).dump();
    out.push_back(e);
  }
  return out;
}

}  // namespace rotlie::runs
