#pragma once
// How far a fixed-step spin–orbit run can be trusted, by a measure that sees phase errors: the same
// method at about twice the step alongside (Richardson), as binary_estimate.hpp does for the binary.
// The conserved quantity of spin_check stays bounded under a symplectic splitting while the spin angle
// drifts, so it cannot see a wrong phase; two runs of one method at steps h and h' = ρh end apart by
// about (ρ^p − 1) times the error at h (p the method's order). The estimate divides their distance by
// ρ^p − 1.
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
  double step_ratio = 0;     ///< ρ = h'/h
  double cpu_s = 0;          ///< the companion run's stepping CPU
};

/// The companion's estimate for the run of `setup` that ended at attitude Q with body-frame angular
/// velocity omega, or nothing (an adaptive method, fewer than 2 steps, or a companion that failed:
/// `why` says which). `stop` is passed on to the companion (spin_run).
std::optional<spin_error_estimate> estimate_spin_error(const spin_setup& setup, const models::mat3<double>& Q, const models::vec3<double>& omega,
                                                       std::string& why, const std::function<bool()>& stop = {});

}  // namespace rotlie::runs
