// Tides of constant time lag (runs/src/binary_terms/tides_term.cpp, issue 45) against closed forms: the
// conservative part is the gradient of its potential; the total angular momentum is kept while the energy
// falls; and on a circular orbit about a point-mass pair (order 0) with the primary spinning faster than the
// orbit, the secular rates of Mignard's force averaged over the orbit,
//   F_θ = 3 k₂ G m₂² R⁵ Δt (Ω − n) / a⁷,  da/dt = 2 F_θ / (μ n),  dn/dt = −(3/2)(n/a) da/dt,
//   dΩ/dt = −a F_θ / C,
// are met by an RKF78 run of twenty orbits (the tide exaggerated, k₂ = 1 and Δt = 600 s, so that a moves
// by metres).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_terms.hpp"

BOOST_AUTO_TEST_SUITE(tides_term_test)

using namespace rotlie;

namespace {

runs::binary_request tidal_request(const std::string& tides, const std::string& T) {
  runs::binary_request r;
  r.system = "didymos", r.order = "0", r.integrator = "odeint-rkf78:1e-13", r.h = "600", r.T = T;
  r.terms["tides"] = tides;
  return r;
}

double unwrap(double angle, double previous) {
  const double turn = 2 * std::acos(-1.0);
  while (angle - previous > turn / 2) angle -= turn;
  while (angle - previous < -turn / 2) angle += turn;
  return angle;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_force_and_torques_are_the_potentials_gradient_without_lag) {
  const auto s = runs::binary_setup_of(tidal_request("1,0,0.5,0", "0"));
  const auto sys = s.system_model();
  auto x = s.start;
  x.r = {1.1, 0.3, -0.2};
  const auto f = sys.terms().front();
  models::mutual_gravity<double> at;
  f->add(x, 0.0, at);
  for (std::size_t c = 0; c < 3; ++c) {
    const double dx = 1e-6;
    auto up = x, down = x;
    up.r[c] += dx, down.r[c] -= dx;
    models::mutual_gravity<double> fu, fd;
    f->add(up, 0.0, fu), f->add(down, 0.0, fd);
    BOOST_TEST(at.F[c] == -(fu.U - fd.U) / (2 * dx), boost::test_tools::tolerance(1e-7));
  }
  // without lag the bulge points at the other body: no torque
  for (std::size_t c = 0; c < 3; ++c) BOOST_TEST(std::abs(at.M1[c]) + std::abs(at.M2[c]) < 1e-12 * std::abs(at.F[0]));
}

BOOST_AUTO_TEST_CASE(the_lag_keeps_the_angular_momentum_and_dissipates_energy) {
  const auto run = runs::binary_run(runs::binary_setup_of(tidal_request("1,600,1,600", "199800")));
  const auto sys = run.setup.system_model();
  const double E0 = sys.energy(run.setup.start, 0.0);
  BOOST_TEST_MESSAGE("L kept to " << run.check.max_rel_angular_momentum_error << "; the energy falls from " << E0 << " to " << run.end.energy);
  BOOST_TEST(run.check.max_rel_angular_momentum_error < 1e-11);
  BOOST_TEST(!run.check.unstable);
  BOOST_TEST(run.end.energy < E0);  // the primary spins faster than the orbit: energy falls
}

BOOST_AUTO_TEST_CASE(the_secular_rates_on_a_circular_orbit_are_the_closed_forms) {
  auto q = tidal_request("1,600,0,0", "0");
  const auto s0 = runs::binary_setup_of(q);
  const auto sys = s0.system_model();
  const double G = sys.G(), m1 = sys.body(0).mass, m2 = sys.body(1).mass, mu = sys.reduced_mass();
  const auto& I = sys.moments(0);
  const double R = std::sqrt(5 * (I[0] + I[1] + I[2]) / (6 * m1)), a = s0.start.r[0];
  const double n = std::sqrt(G * (m1 + m2) / (a * a * a)), Omega = s0.start.body[0].G[2] / I[2];
  // the closed forms at a separation a and spin Ω (n from Kepler's third law)
  struct rates {
    double a_dot, n_dot, Omega_dot;
  };
  const auto closed_form = [&](double a_, double Omega_) {
    const double n_ = std::sqrt(G * (m1 + m2) / (a_ * a_ * a_));
    const double F_theta = 3 * 1.0 * G * m2 * m2 * std::pow(R, 5) * 600 * (Omega_ - n_) / std::pow(a_, 7);
    const double a_dot = 2 * F_theta / (mu * n_);
    return rates{a_dot, -1.5 * n_ / a_ * a_dot, -a_ * F_theta / I[2]};
  };

  const double period = 2 * std::acos(-1.0) / n;
  const long orbits = 20, per_orbit = 72;
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", period / per_orbit);
  q.h = text;
  std::snprintf(text, sizeof text, "%.17g", static_cast<double>(orbits * per_orbit) * std::stod(q.h));
  q.T = text;
  q.every = "1";
  std::vector<double> t, phase, sep;
  const auto run = runs::binary_run(runs::binary_setup_of(q), [&](const runs::binary_sample& x) {
    t.push_back(x.t);
    const double p = std::atan2(x.x.r[1], x.x.r[0]);
    phase.push_back(phase.empty() ? p : unwrap(p, phase.back()));
    sep.push_back(models::norm(x.x.r));
  });
  // a: the mean separation over the first and the last orbit
  const auto mean = [&](std::size_t from) {
    double sum = 0;
    for (std::size_t k = from; k < from + per_orbit; ++k) sum += sep[k];
    return sum / per_orbit;
  };
  const double span = t[t.size() - 1 - per_orbit / 2] - t[per_orbit / 2];
  const double a_rate = (mean(sep.size() - 1 - per_orbit) - mean(0)) / span;
  // n: the phase's curvature, by a least-squares quadratic in t
  double S[5] = {}, P[3] = {};
  for (std::size_t k = 0; k < t.size(); ++k) {
    double tk = 1;
    for (int j = 0; j < 5; ++j) {
      if (j < 3) P[j] += tk * phase[k];
      S[j] += tk;
      tk *= t[k];
    }
  }
  // normal equations for phase = c0 + c1 t + c2 t²
  const double A[3][3] = {{S[0], S[1], S[2]}, {S[1], S[2], S[3]}, {S[2], S[3], S[4]}};
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  const double det2 = A[0][0] * (A[1][1] * P[2] - P[1] * A[2][1]) - A[0][1] * (A[1][0] * P[2] - P[1] * A[2][0]) + P[0] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  const double n_rate = 2 * det2 / det;
  const double Omega_end = run.end.x.body[0].G[2] / I[2], Omega_rate = (Omega_end - Omega) / run.end.t;
  // a moves by 1 % over the run: the rates at the run's middle (a and Ω halfway), second order in the change
  const auto mid = closed_form((mean(0) + mean(sep.size() - 1 - per_orbit)) / 2, (Omega + Omega_end) / 2);
  const double a_dot = mid.a_dot, n_dot = mid.n_dot, Omega_dot = mid.Omega_dot;
  BOOST_TEST_MESSAGE("da/dt " << a_rate << " km/s (closed form " << a_dot << "), dn/dt " << n_rate << " (" << n_dot << "), dOmega/dt " << Omega_rate
                              << " (" << Omega_dot << ")");
  BOOST_TEST(a_rate == a_dot, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(n_rate == n_dot, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(Omega_rate == Omega_dot, boost::test_tools::tolerance(2e-3));
}

BOOST_AUTO_TEST_SUITE_END()
