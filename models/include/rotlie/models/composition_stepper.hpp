#pragma once
// Any scheme table run on a free rigid body: the composition engine on the free_rigid_body system
// (one rotation per stage, each with its precomputed rate, and for the RS splitting one rotation
// about the angular momentum per step: cost (N+1)·C0).
#include "rotlie/models/free_rigid_body.hpp"

namespace rotlie::models {

/// The engine type of every free-body run.
template <class T>
using free_body_composition = composition<free_rigid_body<T>>;

/// A table bound to a body's moments (throws std::invalid_argument for a bad table or body).
template <class T>
free_body_composition<T> free_body_method(const schemes::scheme_table& table, const vec3<T>& I) {
  return free_body_composition<T>(table, free_rigid_body<T>(I));
}

/// The former name, built from (table, I); kept for the callers that construct it directly.
template <class T>
class composition_stepper : public free_body_composition<T> {
 public:
  composition_stepper(const schemes::scheme_table& table, const vec3<T>& I)
      : free_body_composition<T>(table, free_rigid_body<T>(I)) {}
};

}  // namespace rotlie::models
