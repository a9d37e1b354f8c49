#include "liquid_water_run.hpp"

namespace rotlie::runs {

models::liquid_water_run_result liquid_water_runs(const models::liquid_water_run_options& o, const models::rigid_bodies_state<double>& start,
                                                  const models::liquid_water_progress& progress) {
  return models::run_liquid_water(o, start, progress);
}

models::liquid_water_nvt_result liquid_water_nvt_run(const models::liquid_water_run_options& o, const models::liquid_water_nvt_options& nvt,
                                                     const models::rigid_bodies_state<double>& start, const models::liquid_water_progress& progress) {
  return models::run_liquid_water_nvt(o, nvt, start, progress);
}

}  // namespace rotlie::runs
