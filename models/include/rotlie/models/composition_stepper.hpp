#pragma once
// Runs any scheme table on a free rigid body: one rotation per stage, each with its precomputed rate,
// and for the RS splitting one rotation about the angular momentum per step (cost (N+1)·C0).
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

#include "rotlie/models/free_rigid_body.hpp"

namespace rotlie::models {

/// The free rigid body under a scheme table (kept for its callers: the composition engine on
/// free_rigid_body, built from the moments).
template <class T>
class composition_stepper : public composition<free_rigid_body<T>> {
 public:
  composition_stepper(const schemes::scheme_table& table, const vec3<T>& I)
      : composition<free_rigid_body<T>>(table, free_rigid_body<T>(I)) {}
};

}  // namespace rotlie::models
