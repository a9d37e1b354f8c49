#pragma once
// V = 0: free bodies. acts() is false, so kicks are skipped and count no force evaluation.
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

template <class T>
struct zero_potential {
  bool acts() const { return false; }
  T evaluate(const std::vector<rigid_body_state<T>>&, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque) const {
    for (auto& f : force) f = vec3<T>{};
    for (auto& t : torque) t = vec3<T>{};
    return T(0);
  }
};

}  // namespace rotlie::models
