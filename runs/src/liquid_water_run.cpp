#include "liquid_water_run.hpp"

namespace rotlie::runs {

models::liquid_water_run_result liquid_water_runs(const models::liquid_water_run_options& o, const models::rigid_bodies_state<double>& start,
                                                  const models::liquid_water_progress& progress) {
  return models::run_liquid_water(o, start, progress);
}

}  // namespace rotlie::runs
