#pragma once
// The full two-body problem on the library floor (`rotlie binary`, `rotlie sweep`, Python's
// rotlie.binary): two rigid bodies in mutual gravity (binary_bodies.hpp), an integrator named as md
// and spin name theirs, the run checked, carried out and judged. Units km, kg, s.
//
// Integrators: the method registry's binary methods (runs/methods.hpp): TV splittings of
// H = T_orbit + T_rot + U (X a rotor or a scheme table, solved for each body's moments), the same
// compositions of H = H_Kepler + T_rot + (U − U₀) (KEPLER…: the Kepler orbit drifts exactly), GUBAS's
// fixed-step RK4 and LGVI (binary_anchors.hpp), Boost.Odeint's adaptive methods.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/binary_system.hpp"
#include "rotlie/models/scenes/spin_orbit_odeint.hpp"
#include "rotlie/runs/binary_bodies.hpp"
#include "rotlie/runs/binary_estimate.hpp"
#include "rotlie/runs/binary_observables.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

/// What a user types (the command line's contract, the strings as given; empty: not given).
struct binary_request {
  std::string system;                   ///< a named system (binary_system_presets), or empty
  std::string primary, secondary;       ///< ellipsoid:a,b,c | polyhedron:FILE
  std::string density;                  ///< kg/m³: one value for both, or two
  std::string mass;                     ///< kg: M1,M2 (instead of the density)
  std::string order = "2";              ///< 0 to 16 (the inertia integrals' total degree)
  std::string G = "6.67430e-20";        ///< km³ kg⁻¹ s⁻²
  std::string separation;               ///< km: the circular start
  std::string primary_period;           ///< hours: the primary's spin in the circular start
  std::string state_file;               ///< JSON with r, v, Q1, Q2, omega1, omega2 (instead of the circular start)
  std::string state_text;               ///< the same JSON as text (a sweep's inline start)
  std::string integrator, h, T;         ///< h and T in seconds (h not needed with T = 0)
  std::string every = "0";              ///< a trajectory sample every K steps (0: none)
  std::map<std::string, std::string> terms;  ///< added force terms by name (binary_terms.hpp): their values as typed
  bool force = false;                        ///< run values that look like unit mistakes (binary_units.hpp)
  std::string impulse;                       ///< an impulse on one body at the start (binary_observables.hpp), or empty
  bool observe = false;                      ///< read the observables off every step (binary_observables.hpp)
  std::string accuracy = "1e-3,1e-2";        ///< the error estimate's bounds: relative (position, velocity), rad (attitudes)
  bool no_error_estimate = false;            ///< skip the run at twice the step (binary_estimate.hpp)
};

struct binary_method {
  enum class kind { splitting, rk4, lgvi, odeint };
  std::string name;
  kind family = kind::splitting;
  models::md_integrator splitting;                    ///< the TV table and the rotor's kind (splittings)
  bool kepler = false;                                ///< the Kepler split's drift
  std::optional<schemes::scheme_table> rotor[2];      ///< each body's rotor table (a table rotor)
  models::odeint_method ode = models::odeint_method::rkf78;
  double tolerance = 1e-12;
};

/// The checked run.
struct binary_setup {
  std::string system;  ///< the named system, or empty
  binary_body primary, secondary;
  double G = 6.67430e-20;
  int order = 2;
  models::binary_state<double> start;
  binary_method method;
  double h = 0, T = 0;  ///< s (h = T/steps, the step used)
  long steps = 0;
  long every = 0;
  std::vector<std::pair<std::string, std::shared_ptr<const registered_term>>> terms;  ///< added force terms, by name
  std::optional<binary_impulse> impulse;  ///< applied to the start given (start holds the pair after it)
  bool observe = false;
  bool error_estimate = true;            ///< a fixed-step run's estimate at twice the step (binary_estimate.hpp)
  double accuracy_rel = 1e-3, accuracy_rad = 1e-2;
  bool stops_at_contact = true;          ///< false only for a companion run that checks a contact (it steps through)

  /// The pair with its added terms.
  models::binary_system<double> system_model() const;
};

/// Throws bad_input (one line naming the option) for anything that does not describe a run: unknown
/// names, non-positive sizes or masses, bodies that overlap at the start, an orbit whose pericentre
/// lies within the bodies' inner radii (it must collide), NaN.
binary_setup binary_setup_of(const binary_request& request);

/// One sample of the trajectory (and the final state).
struct binary_sample {
  double t = 0;
  models::binary_state<double> x;
  double energy = 0;
};

/// What tells whether a run can be trusted: the energy's and the total angular momentum's largest
/// relative changes over the steps; "unstable" when the energy error reaches the mutual potential's own
/// fluctuation along the run (as md's dH/dV ≥ 100 %) beyond round-off, or a value is not finite.
struct binary_check {
  double max_rel_energy_error = 0, max_rel_angular_momentum_error = 0;
  double potential_fluctuation = 0;  ///< max − min of U over the samples (kg km² s⁻²)
  bool unstable = false;
  bool round_off_floor = false;  ///< a step moves the pair by less than 1000 ε: lost in round-off
  bool inaccurate = false;       ///< the error estimate beyond the accuracy asked for
  std::vector<std::string> warnings;
};

struct binary_result {
  binary_setup setup;
  binary_sample end;
  models::vec3<double> angular_momentum{};
  models::mutual_gravity<double> mutual;  ///< at the final state
  binary_check check;
  double cpu_s = 0;
  long evaluations = 0;  ///< mutual-gravity evaluations
  std::optional<binary_observables> observables;  ///< with setup.observe
  std::optional<binary_error_estimate> error_estimate;  ///< with setup.error_estimate, for a fixed-step run
};

/// The bodies came into contact: the run stops (the CLI exits 1 saying when).
struct binary_contact : std::runtime_error {
  binary_contact(double t, long step);
  double t;
  long step;
};

/// A fixed-step run touched, but the state that touched is not known to the accuracy asked for: the
/// same run at half the step puts it elsewhere (binary_estimate.hpp). The contact may be the step's
/// error rather than a physical outcome (the CLI exits 1 saying so).
struct binary_unconfirmed_contact : std::runtime_error {
  binary_unconfirmed_contact(const binary_contact& seen, const std::string& at_half_step);
  double t;
};

/// Runs the setup; `sample` (if given) receives the state at steps 0, every, 2·every, …, and `progress`
/// (if given) the fraction done about every 1 % of the steps. Throws binary_contact (for a fixed-step
/// method, only once the touching state is confirmed to the accuracy asked for at half the step),
/// binary_unconfirmed_contact, or std::runtime_error when an adaptive run exhausts its step budget.
/// `stop` (if given) is asked every 64 steps; when it says so the run throws binary_stopped.
binary_result binary_run(const binary_setup& setup, const std::function<void(const binary_sample&)>& sample = {},
                         const std::function<void(double)>& progress = {}, const std::function<bool()>& stop = {});

/// The run was stopped before its end (binary_run's `stop`): no result.
struct binary_stopped : std::runtime_error {
  binary_stopped() : std::runtime_error("the run was stopped before its end") {}
};

}  // namespace rotlie::runs
