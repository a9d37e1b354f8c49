// The measurements of the report's section on the exact free-body flow's hard regimes (see
// exact_flow_study.hpp): the float128 instance is itself checked against an independent float128
// Runge-Kutta solution by exact_flow_regimes_test.
#include "rotlie/runs/exact_flow_study.hpp"

#include <algorithm>
#include <cmath>

#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::runs {
namespace {

using models::vec3;

vec3<quad> wide(const vec3<double>& v) { return {quad(v[0]), quad(v[1]), quad(v[2])}; }

// Max abs entry error of Q and of G/|G| over 16 times in (0, T]; the flow composed of two halves at T.
exact_flow_measured measure(const exact_flow_regime& r) {
  models::body_state<double> s0;
  s0.G = r.G;
  models::body_state<quad> q0;
  q0.G = wide(r.G);
  const models::exact_free_body<double> flow(r.I, s0);
  const models::exact_free_body<quad> reference(wide(r.I), q0);
  const double g_norm = std::sqrt(r.G[0] * r.G[0] + r.G[1] * r.G[1] + r.G[2] * r.G[2]);
  exact_flow_measured m;
  m.mc = static_cast<double>(flow.complementary_parameter());
  for (int k = 1; k <= 16; ++k) {
    const double t = r.T * k / 16;
    const auto a = flow.evaluate(t);
    const auto b = reference.at(quad(t));
    for (std::size_t i = 0; i < 9; ++i) m.q = std::max(m.q, std::abs(static_cast<double>(quad(a.state.Q.a[i]) - b.Q.a[i])));
    for (std::size_t i = 0; i < 3; ++i)
      m.g = std::max(m.g, std::abs(static_cast<double>((quad(a.state.G[i]) - b.G[i]) / quad(g_norm))));
    m.estimate = std::max(m.estimate, a.error_estimate);
  }
  const models::exact_free_body<double> second(r.I, flow.at(r.T / 2));
  const auto twice = second.at(r.T / 2);
  const auto truth = reference.at(quad(r.T));
  for (std::size_t i = 0; i < 9; ++i) m.composed = std::max(m.composed, std::abs(static_cast<double>(quad(twice.Q.a[i]) - truth.Q.a[i])));
  return m;
}

std::vector<exact_flow_regime> regimes(bool quick) {
  const vec3<double> water{10220.0 / 29376, 19187.0 / 29376, 1};
  std::vector<exact_flow_regime> r;
  for (int e = 2; e <= 15; e += quick ? 4 : 1) {
    const double d = std::pow(10.0, -e);
    r.push_back({"middle axis, water, G(0) = (d, 1, d)", "d = " + runs::scientific_text(d, 1), water, {d, 1, d}, 3, d});
  }
  r.push_back({"on the separatrix, I = (3, 15/4, 5)", "G(0) = (1, 1/2, 1)", {3, 3.75, 5}, {1, 0.5, 1}, 10});
  r.push_back({"on the separatrix, I = (3, 15/4, 5)", "G(0) = (−1, 1/2, 1)", {3, 3.75, 5}, {-1, 0.5, 1}, 10});
  for (int e = 3; e <= 12; e += quick ? 9 : 3) {
    const double a = std::pow(10.0, -e);
    r.push_back({"near-spherical, prolate (1, 1, 1 + a)", "a = " + runs::scientific_text(a, 1), {1, 1, 1 + a}, {0.3, 1, 0.7}, 3});
    r.push_back({"near-spherical, oblate (1, 1 + a, 1 + a)", "a = " + runs::scientific_text(a, 1), {1, 1 + a, 1 + a}, {0.3, 1, 0.7}, 3});
    r.push_back({"near-spherical, triaxial (1, 1 + a, 1 + 2a)", "a = " + runs::scientific_text(a, 1), {1, 1 + a, 1 + 2 * a}, {0.3, 1, 0.7}, 3, a});
  }
  r.push_back({"thin rod (1e-8, 1, 1)", "T = 1 (3e7 rad of spin)", {1e-8, 1, 1}, {0.3, 1, 0.7}, 1});
  r.push_back({"flat, I1 + I2 = I3", "(1/4, 3/4, 1)", {0.25, 0.75, 1}, {0.3, 1, 0.7}, 3});
  r.push_back({"flat, near-symmetric", "(1/2, 1/2 + 1e-9, 1)", {0.5, 0.5 + 1e-9, 1}, {0.3, 1, 0.7}, 3});
  for (const double s : {1e-150, 1e-20, 1e20, 1e150})
    r.push_back({"‖G‖ scaled, I = (0.4, 0.7, 1)", "‖G‖ ≈ " + runs::scientific_text(s, 1), {0.4, 0.7, 1}, {0.1 * s, s, 0.2 * s}, 3 / s});
  for (const double T : {1e3, 1e6}) r.push_back({"long time, water, G(0) = (1, 1, 1)", "T = " + runs::scientific_text(T, 1), water, {1, 1, 1}, T});
  return r;
}

}  // namespace

std::vector<exact_flow_case> exact_flow_study(bool quick) {
  std::vector<exact_flow_case> out;
  for (const auto& r : regimes(quick)) out.push_back({r, measure(r)});
  return out;
}

}  // namespace rotlie::runs
