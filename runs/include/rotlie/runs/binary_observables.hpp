#pragma once
// What binary-asteroid researchers read off a run, on the floor for every front end (`rotlie binary
// --observe`, Python, the report): the mutual orbit's osculating elements and mean period, the
// secondary's libration (its long axis against the line of centres: the series, amplitude, mean and
// period), both spin periods, each body's attitude in the orbit frame (roll, pitch, yaw) and its
// non-principal-axis rotation (the angle of G off the maximum-moment axis, the dynamical inertia, the
// mode and the tumbling flag), and an impulsive Δv on either body (DART's, as a vector or as β m U / M).
#include <array>
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

/// The orbit frame at x, as the columns of a rotation (orbit → inertial): x̂ = r̂ (from the primary toward
/// the secondary), ẑ along r × v (the mutual orbit's normal), ŷ = ẑ × x̂. False when r × v vanishes.
bool orbit_frame(const models::binary_state<double>& x, models::mat3<double>& frame);

/// Body k's principal axes in the orbit frame as 1-2-3 Euler angles {roll φ, pitch θ, yaw ψ} (rad): the
/// attitude R = Fᵀ Q (F the orbit frame) is R_x(φ) R_y(θ) R_z(ψ), a turn φ about x̂, then θ about the
/// turned ŷ, then ψ about the twice-turned ẑ; θ in [−π/2, π/2], φ and ψ in (−π, π]. The principal axes carry
/// no arrow: of the four attitudes a half turn about a body axis apart (R D, D = diag(±1, ±1, ±1) with
/// det D = 1) the one nearest the orbit frame (the largest trace) is read, so a body at rest in the frame
/// reads 0, and on a planar orbit yaw is the libration angle and roll and pitch are 0. Returns zeros when
/// the orbit frame does not exist.
models::vec3<double> orbit_euler_angles(const models::binary_state<double>& x, int body);

/// The angle (rad, in [0, π/2]) between a body-frame angular momentum G and the body's maximum-moment
/// axis C: atan2(|G − G_C ĉ|, |G_C|). When two moments share the maximum (within 1e-12 of the trace),
/// the angle to their plane; 0 for a sphere or G = 0.
double max_moment_angle(const models::vec3<double>& I, const models::vec3<double>& G);

/// The dynamical inertia I_d = |G|² / (2E), E = Σ G_k² / (2 I_k) the rotational energy: in [A, C], C for a
/// pure spin about the maximum-moment axis, A about the minimum-moment axis (Kaasalainen 2001; Pravec et
/// al. 2005). G = 0 gives C.
double dynamical_inertia(const models::vec3<double>& I, const models::vec3<double>& G);

/// One body's rotation read off a run.
struct body_rotation {
  models::vec3<double> euler_max_deg{};  ///< the largest |roll|, |pitch|, |yaw| over the samples (orbit_euler_angles)
  models::vec3<double> euler_end_deg{};  ///< roll, pitch, yaw at the end
  double npa_angle_max_deg = 0;          ///< the largest angle between G and the maximum-moment axis over the samples
  double npa_angle_end_deg = 0;          ///< the same at the end
  double id_over_c = 1;                  ///< I_d / C at the end
  bool short_axis_mode = true;           ///< I_d ≥ B at the end (SAM: the polhode circles C); else LAM (it circles A)
  bool tumbling = false;                 ///< npa_angle_max_deg above the threshold
};

/// The default threshold of the tumbling flag (degrees of G off the maximum-moment axis).
constexpr double default_tumbling_threshold_deg = 1;

/// What is read off a trajectory sampled at regular times.
struct binary_observables {
  double orbit_period_h = 0;           ///< the mean mutual orbit period (the orbital angle's least-squares slope), hours
  double libration_amplitude_deg = 0;  ///< half the range of the libration angle
  double libration_mean_deg = 0;
  double libration_period_h = 0;  ///< the mean spacing of its upward crossings of the mean, hours (0: none seen)
  double primary_period_h = 0, secondary_period_h = 0;  ///< at the end
  double separation_min_km = 0, separation_max_km = 0;
  osculating_orbit osculating;  ///< at the end
  body_rotation rotation[2];    ///< the primary's and the secondary's
  double tumbling_threshold_deg = default_tumbling_threshold_deg;
};

/// Collects the samples (add at each) and reads the observables.
class binary_observer {
 public:
  explicit binary_observer(double tumbling_threshold_deg = default_tumbling_threshold_deg) : threshold_deg_(tumbling_threshold_deg) {}
  void add(double t, const models::binary_state<double>& x);
  binary_observables result(const models::binary_system<double>& sys, const models::binary_state<double>& end) const;
  const std::vector<double>& times() const { return t_; }
  const std::vector<double>& libration() const { return phi_; }  ///< rad, at times()

 private:
  std::vector<double> t_, theta_, phi_;
  double unwrapped_ = 0, last_ = 0, d_min_ = 0, d_max_ = 0;
  double threshold_deg_;
  // per body and body axis k, over the samples: the largest angle of G off axis k and off the plane
  // normal to k (which of them is the maximum-moment axis is known only with the moments)
  std::array<models::vec3<double>, 2> off_axis_max_{}, off_plane_max_{};
  std::array<models::vec3<double>, 2> euler_max_{};  // rad
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
