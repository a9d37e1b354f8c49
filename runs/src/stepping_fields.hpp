#pragma once
// The JSON fields every fixed-step scene run shares (rotlie spin, rotlie binary): the integrator, the
// step taken, the span, the steps and the force evaluations they cost.
#include <nlohmann/json.hpp>

namespace rotlie::runs {

template <class Setup, class Count>
nlohmann::json stepping_fields(const Setup& s, const Count& evaluations) {
  return {{"integrator", s.method.name}, {"h", s.h}, {"T", s.T}, {"steps", s.steps}, {"evaluations", evaluations}};
}

}  // namespace rotlie::runs
