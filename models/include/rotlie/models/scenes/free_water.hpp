#pragma once
// Scene "free water" (vZS section V.A): one water molecule, V = 0, canonical initial conditions at
// 297 K. Its exact motion is known (exact_free_body), so the orientation error of any integrator
// can be measured against it (experiments/free_water_experiment.hpp).
#include <cstdint>

#include "rotlie/models/scenes/canonical_state.hpp"
#include "rotlie/models/scenes/water.hpp"
#include "rotlie/models/scenes/zero_potential.hpp"
#include "rotlie/models/unit_system.hpp"

namespace rotlie::models {

template <class T>
struct free_water {
  T mass = water::mass<T>();
  vec3<T> moments = water::moments<T>();
  unit_system<T> units = unit_system<T>::real();
  zero_potential<T> potential{};

  /// Run `run` of the ensemble with seed `seed`: one molecule.
  rigid_bodies_state<T> initial(std::uint64_t seed, std::uint64_t run) const {
    rigid_bodies_state<T> s;
    s.bodies.push_back(canonical_state<T>(seed, run, mass, moments, water::temperature));
    return s;
  }
};

}  // namespace rotlie::models
