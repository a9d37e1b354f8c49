#pragma once
// How far a fixed-step binary run can be trusted, by a measure that sees phase errors: the same method
// at about twice the step alongside (Richardson). A symplectic splitting keeps the energy bounded while
// its orbital and rotational phases drift, so the energy cannot see a wrong phase; two runs of one method
// at steps h and h' = ρh end apart by about (ρ^p − 1) times the error at h (p the method's order), phase
// errors included. The estimate divides their distance by ρ^p − 1, with p the order a third run at about
// 4h shows (short of the asymptotic range the distances shrink slower than the declared order says).
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
  double observed_order = 0;  ///< the lowest order the companions show, in [1, p] (p when not checked)
  double step_ratio = 0;    ///< ρ = h'/h of the companion the estimate divides by (0.5: the run at half the step)
  double cpu_s = 0;         ///< the companion run's stepping CPU
};

/// The companions' estimate for the run of `setup` that ended at `end`: runs at about 2h and 4h (the
/// second checks the order the first assumes; about 75 % more CPU); also at h/2 when the run at 4h ends
/// a radian or the orbit's size away (it then says nothing of the order), and for runs of fewer than 4
/// steps or whose run at 2h fails. Nothing for an adaptive method, or when the companions touched or
/// failed (`why` says which: the run's accuracy is then unknown).
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
