#pragma once
// The spin–orbit scene on the library floor (`rotlie spin`, the report's "Spin–orbit" section and
// bench/spin_bench): a body named or given as A,B,C, an integrator named as the command line names it,
// the run checked and carried out in double, long double or float128.
//
// Named bodies (moments with C = 1; the orbit's eccentricity beside them):
//   Hyperion  uniform ellipsoid of semi-axes 190 × 145 × 114 km, (B − A)/C = 0.264, i.e. Wisdom,
//             Peale & Mignard (1984)'s ω₀ = √(3(B − A)/C) = 0.89; e = 0.1
//   Moon      β = (C − A)/B = 631.0e-6, γ = (B − A)/C = 227.7e-6 (lunar laser ranging and GRAIL,
//             Williams et al. 2014); e = 0.0549
//   Mercury   C/MR² = 0.346 (Margot et al. 2012), J₂ = 5.031e-5 and C₂₂ = 0.809e-5 (MESSENGER,
//             Smith et al. 2012): (B − A)/C = 4C₂₂/(C/MR²) = 9.35e-5, (C − A)/C = (J₂ + 2C₂₂)/(C/MR²); e = 0.2056
#include <array>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/spin_orbit_odeint.hpp"
#include "rotlie/models/small_matrix.hpp"
#include "rotlie/runs/spin_estimate.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

/// A body of the scene: moments A ≤ B ≤ C as exact text "A,B,C" (named bodies: C = 1).
struct spin_body {
  std::string name;        ///< Hyperion, Moon, Mercury, or the moments as typed
  std::string moments;     ///< "A,B,C", exact decimals or rationals
  double orbit_e = 0;      ///< the real orbit's eccentricity (named bodies)
  std::string source;      ///< where the moments come from
};

/// The named bodies, in the order above.
const std::vector<spin_body>& spin_bodies();

/// A name of spin_bodies() or "A,B,C" with 0 < A ≤ B ≤ C (eq. 77); throws bad_input naming --body.
spin_body spin_body_named(const std::string& text);

/// An integrator of the scene, named as the method registry's spin methods (runs/methods.hpp): a splitting
/// with its rotor table resolved for the body, or a Boost.Odeint adaptive method (TOL within 5 ε of the
/// scalar … 1e-2: spin_method_named takes long double's floor, spin_setup_of the run's).
struct spin_method {
  std::string name;
  bool adaptive = false;                       ///< an Odeint method
  int order = 0;                               ///< the declared order (a rotor table of lower order lowers it)
  models::odeint_method ode = models::odeint_method::dopri5;
  double tolerance = 1e-10;                    ///< absolute and relative (Odeint)
  double first_step = 0;                       ///< Odeint's first trial step (time units); 0: the run's step h
  models::md_integrator splitting;             ///< the TV table and rotor (splittings)
  std::optional<schemes::scheme_table> rotor;  ///< the rotor table solved or read for the body
};

/// Throws bad_input naming --integrator.
spin_method spin_method_named(const std::string& name, const spin_body& body);

/// What a user types (the command line's contract, the strings as given).
struct spin_request {
  std::string body, e, integrator, h, T, theta0 = "0", omega0 = "1", obliquity = "0", scalar = "double";
  std::string every = "0";  ///< a trajectory sample every K steps (0: none)
  std::string accuracy = "1e-3,1e-2";  ///< the error estimate's bounds: REL (spin rate) or REL,RAD (attitude)
  bool no_error_estimate = false;      ///< skip the run at twice the step (spin_estimate.hpp)
};

/// The checked run: h a fraction of the orbital period, T in orbits, T a whole number of steps h
/// (exactly, or within 1e-9 relative for decimals typed from a float: then h = T/steps, the step
/// used, which the JSON reports). An adaptive method takes h as its first trial step and lands on
/// every multiple of h, where the conserved quantity is sampled.
struct spin_setup {
  spin_body body;
  spin_method method;
  double e = 0, h = 0, T = 0, theta0 = 0, omega0 = 1, obliquity = 0;
  long steps = 0;
  long every = 0;  ///< trajectory samples at steps 0, K, 2K, … (0: none)
  std::string scalar = "double";
  bool error_estimate = true;  ///< a fixed-step run's estimate at twice the step (spin_estimate.hpp)
  double accuracy_rel = 1e-3, accuracy_rad = 1e-2;
};

/// Throws bad_input (one line naming the option) for anything that does not describe a run.
spin_setup spin_setup_of(const spin_request& request);

/// What tells whether a run can be trusted: a quantity the exact flow conserves, sampled after every
/// step. At e = 0 the Jacobi integral J = T + V − L_z; otherwise the extended-phase-space
/// Hamiltonian K = T + V' + p_t, V' the potential without its isotropic part and p_t = −∫ ∂V'/∂t dt
/// (the trapezoidal rule over the steps). "unstable": its largest change reaches the potential's own
/// fluctuation along the run (the criterion of md's dH/dV ≥ 100 %) and lies beyond round-off, or
/// the final spin or energy is not finite, or the attitude is no longer a rotation (|QᵀQ − 1| > 1e-3).
/// "inaccurate": the error estimate (spin_estimate.hpp) beyond the accuracy asked for.
struct spin_check {
  std::string quantity;           ///< "jacobi" or "extended_hamiltonian"
  double start = 0;               ///< its value at t = 0
  double max_change = 0;          ///< max |K(t_k) − K(0)| over the steps
  double potential_fluctuation = 0;  ///< max − min of V' over the steps
  double change_percent = 0;      ///< 100 max_change / potential_fluctuation (inf when V' is steady)
  bool unstable = false;
  bool round_off_floor = false;   ///< a step turns the body by less than 1000 ε: the step is lost in round-off
  bool inaccurate = false;        ///< the error estimate beyond the accuracy asked for
  std::vector<std::string> warnings;  ///< one line per flag
};

/// The state every K steps (spin_setup::every), from the start: time in orbits, attitude (row-major,
/// columns the body axes), angular velocity in the body frame (units of n), energy T + V(t).
struct spin_trajectory {
  std::vector<double> t;
  std::vector<std::array<double, 9>> Q;
  std::vector<std::array<double, 3>> omega_body;
  std::vector<double> energy;
};

struct spin_result {
  spin_setup setup;
  spin_check check;
  spin_trajectory trajectory;  ///< empty unless setup.every > 0
  models::mat3<double> Q{};         ///< final attitude: columns the body axes A, B, C in the inertial frame
  models::vec3<double> omega_body{};  ///< final angular velocity in the body frame (units of n)
  double theta = 0;                 ///< the A axis' angle in the inertial xy plane
  double energy_start = 0, energy_end = 0;  ///< T + V(t) at 0 and at the end
  double cpu_s = 0;                 ///< CPU seconds of the stepping
  long evaluations = 0;             ///< torque evaluations (force_evaluations; right-hand sides for Odeint)
  std::optional<spin_error_estimate> error_estimate;  ///< with setup.error_estimate, for a fixed-step run
};

/// The largest number of steps an adaptive run may take per orbit of T (accepted and refused): a
/// tolerance the problem cannot reach ends the run with an error instead of running for days.
inline constexpr double adaptive_steps_per_orbit = 1e6;

/// Runs the setup in its scalar, then (setup.error_estimate) its companion at twice the step. Throws
/// std::runtime_error when the run diverges or an adaptive run exhausts its step budget. `stop` (if
/// given) is asked every 64 steps; when it says so the run throws spin_stopped.
spin_result spin_run(const spin_setup& setup, const std::function<bool()>& stop = {});

/// The run was stopped before its end (spin_run's `stop`): no result.
struct spin_stopped : std::runtime_error {
  spin_stopped() : std::runtime_error("the run was stopped before its end") {}
};

/// The moments of a body in double (A, B, C).
models::vec3<double> spin_moments(const spin_body& body);

}  // namespace rotlie::runs
