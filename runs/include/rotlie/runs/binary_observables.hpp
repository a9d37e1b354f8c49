#pragma once
// What binary-asteroid researchers read off a run, on the floor for every front end (`rotlie binary
// --observe`, Python, the report): the mutual orbit's osculating elements and mean period, the
// secondary's libration (its long axis against the line of centres: the series, amplitude, mean and
// period), both spin periods, and an impulsive Δv on either body (DART's, as a vector or as β m U / M).
#include <string>
#include <vector>

#include "rotlie/models/scenes/binary_system.hpp"

namespace rotlie::runs {

/// Two-body elements of (r, v) about G(M₁ + M₂), in the inertial frame (z the primary's pole at a
/// circular start). An unbound orbit has period 0 and a < 0.
struct osculating_orbit {
  double a_km = 0, e = 0, i_deg = 0, period_h = 0;
};
osculating_orbit osculating_elements(const models::binary_state<double>& x, double GM);

/// The secondary's long axis (body x) against the line of centres in the xy plane, in (−π/2, π/2]
/// (the axis has no arrow).
double libration_angle(const models::binary_state<double>& x);

/// 2π/|ωₖ| in hours (0 for a body at rest).
double spin_period_h(const models::binary_system<double>& sys, const models::binary_state<double>& x, int body);

/// What is read off a trajectory sampled at regular times.
struct binary_observables {
  double orbit_period_h = 0;           ///< the mean mutual orbit period (the orbital angle's least-squares slope), hours
  double libration_amplitude_deg = 0;  ///< half the range of the libration angle
  double libration_mean_deg = 0;
  double libration_period_h = 0;  ///< the mean spacing of its upward crossings of the mean, hours (0: none seen)
  double primary_period_h = 0, secondary_period_h = 0;  ///< at the end
  double separation_min_km = 0, separation_max_km = 0;
  osculating_orbit osculating;  ///< at the end
};

/// Collects the samples (add at each) and reads the observables.
class binary_observer {
 public:
  void add(double t, const models::binary_state<double>& x);
  binary_observables result(const models::binary_system<double>& sys, const models::binary_state<double>& end) const;
  const std::vector<double>& times() const { return t_; }
  const std::vector<double>& libration() const { return phi_; }  ///< rad, at times()

 private:
  std::vector<double> t_, theta_, phi_;
  double unwrapped_ = 0, last_ = 0, d_min_ = 0, d_max_ = 0;
};

/// An impulse on one body (0 the primary, 1 the secondary): Δv in km/s, inertial.
struct binary_impulse {
  int body = 1;
  models::vec3<double> dv{};
};

/// `BODY:dx,dy,dz` (mm/s, inertial) or `BODY:beta,m,U` (DART's form: Δv = β m U / M_BODY in mm/s,
/// m in kg and U in km/s, against the body's orbital motion about the barycentre), BODY primary or
/// secondary. Throws bad_input naming --impulse.
binary_impulse impulse_named(const std::string& text, const models::binary_system<double>& sys, const models::binary_state<double>& at);

/// The pair after the impulse: the relative velocity v = v₂ − v₁ changes by ±Δv.
models::binary_state<double> with_impulse(models::binary_state<double> x, const binary_impulse& impulse);

}  // namespace rotlie::runs
