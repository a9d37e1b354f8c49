#include "rotlie/runs/spin_orbit_science.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rotlie/runs/spin_orbit_stepping.hpp"

namespace rotlie::runs {
namespace {

constexpr double pi = boost::math::constants::pi<double>();
constexpr double two_pi = boost::math::constants::two_pi<double>();
constexpr double shadow_distance = 1e-9;

double state_distance(const models::body_state<double>& a, const models::body_state<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < 9; ++i) s += (a.Q.a[i] - b.Q.a[i]) * (a.Q.a[i] - b.Q.a[i]);
  for (std::size_t i = 0; i < 3; ++i) s += (a.G[i] - b.G[i]) * (a.G[i] - b.G[i]);
  return std::sqrt(s);
}

// b moved back towards a to the distance shadow_distance (to first order; Q stays a rotation to 1e-18).
void renormalise(const models::body_state<double>& a, models::body_state<double>& b, double d) {
  const double k = shadow_distance / d;
  for (std::size_t i = 0; i < 9; ++i) b.Q.a[i] = a.Q.a[i] + k * (b.Q.a[i] - a.Q.a[i]);
  for (std::size_t i = 0; i < 3; ++i) b.G[i] = a.G[i] + k * (b.G[i] - a.G[i]);
}

// The shadow of a start: θ₀ + 1e-9 about z (a rotation, so the two start on the same energy shell's neighbourhood).
models::body_state<double> shadow_of(const models::body_state<double>& s) {
  models::body_state<double> b = s;
  b.Q = models::rotation(models::vec3<double>{0, 0, 1}, shadow_distance / std::sqrt(2.0)) * s.Q;
  return b;
}

double half_orbit_angle(const spin_body& body, double e, double p, double theta0, double rate, long steps_per_orbit) {
  const auto I = spin_moments_in<double>(body);
  const auto start = models::spin_orbit_start<double>(I, theta0, rate, 0.0);
  const auto out = step_spin_orbit<double>(spin_method_named("SIER4", body), I, e, start, two_pi / static_cast<double>(steps_per_orbit),
                                           steps_per_orbit / 2);
  return std::remainder(models::spin_angle(out.state) - theta0 - p * pi, pi);  // θ ≡ θ₀ + pπ (mod π) at apocentre
}

// The amplitude of γ's first harmonic over one orbit (samples at M_i = 2π(i + 1)/N): the discrete Fourier
// coefficients, exact for a periodic γ (the runs start on the periodic orbit: no free libration).
double orbital_period_amplitude(const std::vector<double>& gamma) {
  const std::size_t n = gamma.size();
  double c = 0, s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double M = two_pi * (static_cast<double>(i) + 1) / static_cast<double>(n);
    c += gamma[i] * std::cos(M);
    s += gamma[i] * std::sin(M);
  }
  return 2 * std::hypot(c, s) / static_cast<double>(n);
}

// A state and its shadow at shadow_distance, carried one orbit at a time (Benettin's renormalisation):
// growth sums the log of the separation's growth per orbit.
struct shadowed_orbit {
  models::body_state<double> a, b;
  double growth = 0;
  explicit shadowed_orbit(const models::body_state<double>& start) : a(start), b(shadow_of(start)) {}
  void advance(const spin_body& body, double e, long steps_per_orbit) {
    a = spin_orbit_map(body, e, a, steps_per_orbit);
    b = spin_orbit_map(body, e, b, steps_per_orbit);
    const double d = state_distance(a, b);
    if (!(d > 0)) {  // the two met (to round-off): start the shadow again, no growth counted
      b = shadow_of(a);
      return;
    }
    growth += std::log(d / shadow_distance);
    renormalise(a, b, d);
  }
};

}  // namespace

models::body_state<double> spin_orbit_map(const spin_body& body, double e, const models::body_state<double>& s, long steps) {
  static thread_local std::string cached_name;
  static thread_local spin_method sier4;
  if (cached_name != body.moments) {
    sier4 = spin_method_named("SIER4", body);
    cached_name = body.moments;
  }
  return step_spin_orbit<double>(sier4, spin_moments_in<double>(body), e, s, two_pi / static_cast<double>(steps), steps).state;
}

spin_section planar_section(const spin_body& body, double e, const std::vector<std::pair<double, double>>& starts, int orbits,
                            long steps_per_orbit) {
  const auto I = spin_moments_in<double>(body);
  spin_section out;
  for (std::size_t j = 0; j < starts.size(); ++j) {
    shadowed_orbit o(models::spin_orbit_start<double>(I, starts[j].first, starts[j].second, 0.0));
    for (int k = 0; k < orbits; ++k) {
      o.advance(body, e, steps_per_orbit);
      out.trajectory.push_back(static_cast<int>(j));
      out.theta.push_back(std::remainder(models::spin_angle(o.a), pi));
      out.rate.push_back(o.a.G[2] / I[2]);
    }
    out.lyapunov.push_back(o.growth / orbits);
  }
  return out;
}

double lyapunov_per_orbit(const spin_body& body, double e, const models::body_state<double>& start, int orbits, long steps_per_orbit) {
  shadowed_orbit o(start);
  for (int k = 0; k < orbits; ++k) o.advance(body, e, steps_per_orbit);
  return o.growth / orbits;
}

double resonant_rate(const spin_body& body, double e, double p, double lo, double hi, long steps_per_orbit, double theta0) {
  // the sign change of the half-orbit angle nearest the middle of [lo, hi] (a wrap by π is no root)
  const int n = 24;
  double best = -1, best_lo = 0, best_hi = 0;
  double x0 = lo, g0 = half_orbit_angle(body, e, p, theta0, lo, steps_per_orbit);
  for (int i = 1; i <= n; ++i) {
    const double x1 = lo + (hi - lo) * i / n, g1 = half_orbit_angle(body, e, p, theta0, x1, steps_per_orbit);
    if ((g0 <= 0) != (g1 <= 0) && std::abs(g0 - g1) < pi / 2) {
      const double dist = std::abs((x0 + x1) / 2 - (lo + hi) / 2);
      if (best < 0 || dist < best) best = dist, best_lo = x0, best_hi = x1;
    }
    x0 = x1, g0 = g1;
  }
  if (best < 0) throw std::runtime_error("no symmetric periodic orbit found between the given rates");
  double glo = half_orbit_angle(body, e, p, theta0, best_lo, steps_per_orbit);
  for (int i = 0; i < 60 && best_hi - best_lo > 1e-14; ++i) {
    const double mid = (best_lo + best_hi) / 2, gm = half_orbit_angle(body, e, p, theta0, mid, steps_per_orbit);
    if ((gm <= 0) == (glo <= 0))
      best_lo = mid, glo = gm;
    else
      best_hi = mid;
  }
  return (best_lo + best_hi) / 2;
}

double planar_map_trace(const spin_body& body, double e, double theta0, double rate, long steps_per_orbit) {
  // central differences of the one-orbit map in (θ, θ'); the map is smooth, so δ = 1e-6 leaves an
  // error of order δ² in each entry, far below the distance of a trace from ±2 that matters here
  const auto I = spin_moments_in<double>(body);
  const double d = 1e-6;
  auto image = [&](double th, double w) {
    const auto s = spin_orbit_map(body, e, models::spin_orbit_start<double>(I, th, w, 0.0), steps_per_orbit);
    return std::pair<double, double>{models::spin_angle(s), s.G[2] / I[2]};
  };
  const auto tp = image(theta0 + d, rate), tm = image(theta0 - d, rate), wp = image(theta0, rate + d), wm = image(theta0, rate - d);
  const double dtheta_dtheta = std::remainder(tp.first - tm.first, pi) / (2 * d);
  const double drate_drate = (wp.second - wm.second) / (2 * d);
  return dtheta_dtheta + drate_drate;
}

double spin_winding(const spin_body& body, double e, double theta0, double rate, int orbits, long steps_per_orbit) {
  const auto I = spin_moments_in<double>(body);
  double previous = theta0, turned = 0;
  step_spin_orbit<double>(spin_method_named("SIER4", body), I, e, models::spin_orbit_start<double>(I, theta0, rate, 0.0),
                          two_pi / static_cast<double>(steps_per_orbit), steps_per_orbit * orbits,
                          [&](long, const double&, const models::body_state<double>& s) {
                            const double a = models::spin_angle(s);
                            turned += std::remainder(a - previous, two_pi);  // a step turns far less than π
                            previous = a;
                          });
  return turned / (two_pi * orbits);
}

double cayley_coefficient(double p, double e) {
  // the coefficients of (a/r)³ e^{−2if} = Σ H(p, e) e^{−2ipM} to the order in e that Wisdom, Peale &
  // Mignard (1984) quote (Cayley's tables)
  if (p == 1) return 1 - 5 * e * e / 2;
  if (p == 1.5) return 7 * e / 2 - 123 * e * e * e / 16;
  if (p == 2) return 17 * e * e / 2;
  throw std::invalid_argument("cayley_coefficient: p must be 1, 3/2 or 2");
}

std::vector<double> obliquity_history(const spin_body& body, double e, const models::body_state<double>& start, int orbits,
                                      long steps_per_orbit) {
  std::vector<double> out;
  auto s = start;
  for (int k = 0; k < orbits; ++k) {
    s = spin_orbit_map(body, e, s, steps_per_orbit);
    out.push_back(std::acos(std::clamp(s.Q(2, 2), -1.0, 1.0)));
  }
  return out;
}

resonance_run resonance(const spin_body& body, double e, double p, double omega0, int orbits, long steps_per_orbit) {
  const auto I = spin_moments_in<double>(body);
  const auto start = models::spin_orbit_start<double>(I, 0.0, omega0, 0.0);
  resonance_run r;
  std::vector<double> one_orbit;
  double amplitude_sum = 0;
  const double h = two_pi / static_cast<double>(steps_per_orbit);
  step_spin_orbit<double>(spin_method_named("SIER4", body), I, e, start, h, steps_per_orbit * orbits,
                          [&](long k, const double& t, const models::body_state<double>& s) {
                            const double g = std::remainder(models::spin_angle(s) - p * t, pi);
                            r.max_excursion = std::max(r.max_excursion, std::abs(g));
                            one_orbit.push_back(g);
                            if (k % steps_per_orbit == 0) {
                              r.orbit.push_back(t / two_pi);
                              r.gamma.push_back(g);
                              amplitude_sum += orbital_period_amplitude(one_orbit);
                              one_orbit.clear();
                            }
                          });
  r.forced_amplitude = amplitude_sum / orbits;
  return r;
}

std::vector<spin_body_ratios> spin_body_table() {
  std::vector<spin_body_ratios> out;
  for (const auto& b : spin_bodies()) {
    const auto I = spin_moments(b);
    out.push_back({b.name, I[0] / I[2], I[1] / I[2], (I[1] - I[0]) / I[2], b.orbit_e, b.source});
  }
  return out;
}

}  // namespace rotlie::runs
