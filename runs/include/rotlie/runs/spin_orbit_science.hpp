#pragma once
// What the spin–orbit scene shows (the report's "Spin–orbit" section): Wisdom, Peale & Mignard (1984)'s
// planar surface of section, Lyapunov estimates, the tilt instability of the synchronous state, and
// the forced librations of Mercury in 3:2 and of the Moon. Every run is the 3-D scene stepped by SIER4
// (the exact rotor) in double; the orbit is periodic, so one orbit from pericentre is always the same
// map, and a run of k orbits is k applications of it.
#include <string>
#include <vector>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/runs/spin_orbit_run.hpp"

namespace rotlie::runs {

/// One orbit (pericentre to pericentre) of the scene in `steps` steps of SIER4.
models::body_state<double> spin_orbit_map(const spin_body& body, double e, const models::body_state<double>& s, long steps);

/// The planar surface of section: θ (mod π, in (−π/2, π/2]) and dθ/dt / n at each pericentre passage.
struct spin_section {
  std::vector<int> trajectory;       ///< index of the start of each point
  std::vector<double> theta, rate;   ///< the points
  std::vector<double> lyapunov;      ///< per start: the largest Lyapunov exponent estimate, per orbit
};

/// Starts (θ₀, ω₀) at pericentre with obliquity 0, each followed for `orbits` orbits.
spin_section planar_section(const spin_body& body, double e, const std::vector<std::pair<double, double>>& starts, int orbits,
                            long steps_per_orbit);

/// The largest Lyapunov exponent per orbit of a 3-D start (two trajectories 1e-9 apart renormalised
/// every orbit, Benettin et al.): the mean of log(growth) over `orbits` orbits.
double lyapunov_per_orbit(const spin_body& body, double e, const models::body_state<double>& start, int orbits, long steps_per_orbit);

/// The symmetric periodic orbit of the p:1 resonance in the plane: θ = θ₀ at pericentre (0 or π/2, the lines
/// of the time-reversal symmetry) and θ = θ₀ + pπ (mod π) at apocentre; returns its spin rate at pericentre
/// (bisection on the half-orbit map, the root nearest the middle of [lo, hi]). p = 1: the synchronous
/// state; p = 3/2: Mercury's.
double resonant_rate(const spin_body& body, double e, double p, double lo, double hi, long steps_per_orbit, double theta0 = 0);

/// The trace of the planar pericentre map's Jacobian in (θ, θ') at (θ₀, θ'₀) (central differences). At a
/// fixed point, |trace| < 2 is an elliptic point (the centre of an island: the resonance survives) and
/// |trace| > 2 a hyperbolic one (no island). For a small asphericity the p:1 state's trace is
/// 2 cos(2π ω₀ √H(p, e)), ω₀² = 3(B − A)/C: its libration frequency in the averaged pendulum.
double planar_map_trace(const spin_body& body, double e, double theta0, double rate, long steps_per_orbit);

/// The planar spin's mean rate over `orbits` orbits from pericentre, in units of n (the angle turned,
/// unwrapped, over 2π per orbit): p for an orbit of the p:1 resonance.
double spin_winding(const spin_body& body, double e, double theta0, double rate, int orbits, long steps_per_orbit);

/// H(p, e) for p = 1, 3/2, 2 (Wisdom, Peale & Mignard 1984, after Cayley): the strength of the p:1
/// resonance; its island's half-width in θ'/n is ω₀ √|H(p, e)| (the resonance-overlap estimate).
double cayley_coefficient(double p, double e);

/// The obliquity (the C axis' angle from z, radians) at each pericentre passage from the given start.
std::vector<double> obliquity_history(const spin_body& body, double e, const models::body_state<double>& start, int orbits,
                                      long steps_per_orbit);

/// A planar resonance p:1 (p = 1 synchronous, 3/2 Mercury's): the angle γ = θ − p M (mod π) sampled
/// at every step, and the amplitude of its first harmonic, |(2/N) Σ γ e^{iM}| over each orbit, averaged
/// over the orbits (the forced libration).
struct resonance_run {
  std::vector<double> orbit, gamma;
  double forced_amplitude = 0;   ///< radians
  double max_excursion = 0;      ///< max |γ| (radians): bounded when the body stays in resonance
};
/// Started at θ = 0 at pericentre with spin rate omega0 (the periodic orbit's, so that no free libration is excited).
resonance_run resonance(const spin_body& body, double e, double p, double omega0, int orbits, long steps_per_orbit);

/// A named body's moments with C = 1 and its orbit, as the report's table of bodies lists them.
struct spin_body_ratios {
  std::string name;
  double a_over_c = 0, b_over_c = 0, asphericity = 0;  ///< A/C, B/C, (B − A)/C
  double e = 0;
  std::string source;
};
std::vector<spin_body_ratios> spin_body_table();

}  // namespace rotlie::runs
