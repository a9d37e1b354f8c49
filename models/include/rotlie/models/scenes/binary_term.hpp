#pragma once
// One force term of the full two-body problem beside the bodies' mutual gravity (the contract every
// added force keeps): at a configuration and a time, its potential, its force on the relative
// coordinate (μ r̈ = F, F the force on body 2 less the reduced share of body 1's) and each body's
// torque about its own centre (inertial frame). The splittings kick with it, the Runge–Kutta anchors
// add it to the derivative, the Kepler split keeps it out of the drift.
#include "rotlie/models/scenes/mutual_gravity.hpp"

namespace rotlie::models {

template <class T>
struct binary_state;

template <class T>
class binary_term {
 public:
  virtual ~binary_term() = default;

  /// Adds U, F, M1 and M2 at (x, t) to `forces`.
  virtual void add(const binary_state<T>& x, const T& t, mutual_gravity<T>& forces) const = 0;

  /// Whether the term depends on time (the energy is then not conserved).
  virtual bool time_dependent() const = 0;

  /// Whether the energy is conserved with the term (a dissipative term, such as a lagging tide, keeps
  /// the total angular momentum while the energy falls).
  virtual bool conserves_energy() const { return !time_dependent(); }
};

}  // namespace rotlie::models
