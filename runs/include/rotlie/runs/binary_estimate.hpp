#pragma once
// How far a fixed-step binary run can be trusted, by a measure that sees phase errors: the same method
// at about twice the step alongside (Richardson). A symplectic splitting keeps the energy bounded while
// its orbital and rotational phases drift, so the energy cannot see a wrong phase; two runs of one method
// at steps h and h' = ρh end apart by about (ρ^p − 1) times the error at h (p the method's order), phase
// errors included. The estimate divides their distance by ρ^p − 1.
#include <functional>
#include <optional>

#include "rotlie/models/scenes/binary_system.hpp"

namespace rotlie::runs {

struct binary_setup;

/// The estimated error of the final state at step h.
struct binary_error_estimate {
  double position_rel = 0, velocity_rel = 0;  ///< |Δr|/|r|, |Δv|/|v|
  double attitude1_rad = 0, attitude2_rad = 0;  ///< the angle of Q_h' ᵀ Q_h, each body
  int order = 0;            ///< p, the method's declared order
  double step_ratio = 0;    ///< ρ = h'/h
  double cpu_s = 0;         ///< the companion run's stepping CPU
};

/// The companion's estimate for the run of `setup` that ended at `end`, or nothing (an adaptive
/// method, fewer than 2 steps, or a companion that touched or failed: `why` says which).
std::optional<binary_error_estimate> estimate_binary_error(const binary_setup& setup, const models::binary_state<double>& end, std::string& why,
                                                           const std::function<bool()>& stop = {});

/// The estimated error of the state `touching` that a run of `setup` reached at step `step` (where the
/// bodies touched), from the same method at half the step stepping through the contact to the same
/// time; nothing for fewer than 1 step or a companion that failed (`why` says so).
std::optional<binary_error_estimate> estimate_contact_error(const binary_setup& setup, long step, const models::binary_state<double>& touching,
                                                            std::string& why, const std::function<bool()>& stop = {});

/// The angle of the rotation Aᵀ B, rad.
double rotation_angle(const models::mat3<double>& A, const models::mat3<double>& B);

}  // namespace rotlie::runs
