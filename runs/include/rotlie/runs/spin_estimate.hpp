#pragma once
// How far a fixed-step spin–orbit run can be trusted, by a measure that sees phase errors: the same
// method at about twice the step alongside (Richardson), as binary_estimate.hpp does for the binary.
// The conserved quantity of spin_check stays bounded under a symplectic splitting while the spin angle
// drifts, so it cannot see a wrong phase; two runs of one method at steps h and h' = ρh end apart by
// about (ρ^p − 1) times the error at h (p the method's order). The estimate divides their distance by
// ρ^p − 1, with p the order a third run at about 4h shows, and takes the run at h/2 instead when the run
// at 4h ends a radian away (as binary_estimate.hpp does).
#include <functional>
#include <optional>
#include <string>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

struct spin_setup;

/// The estimated error of the final state at step h.
struct spin_error_estimate {
  double attitude_rad = 0;   ///< the angle of Q_h'ᵀ Q_h (in the plane: the error of θ)
  double spin_rate_rel = 0;  ///< |Δω|/max(|ω|, n), ω the angular velocity in the body frame (units of n)
  int order = 0;             ///< p, the method's declared order
  double observed_order = 0;  ///< the lowest order the companions show, in [1, p]
  double step_ratio = 0;     ///< ρ = h'/h of the companion the estimate divides by (0.5: the run at half the step)
  double cpu_s = 0;          ///< the companion run's stepping CPU
};

/// The companions' estimate for the run of `setup` that ended at attitude Q with body-frame angular
/// velocity omega (runs at about 2h and 4h; at h/2 as well when the 4h run is a radian away, or alone
/// for fewer than 4 steps or a failed 2h run), or nothing (an adaptive method, no step, or companions
/// that failed: `why` says which). `stop` is passed on to the companion (spin_run).
std::optional<spin_error_estimate> estimate_spin_error(const spin_setup& setup, const models::mat3<double>& Q, const models::vec3<double>& omega,
                                                       std::string& why, const std::function<bool()>& stop = {});

}  // namespace rotlie::runs
