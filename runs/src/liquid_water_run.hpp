#pragma once
// models::run_liquid_water compiled in one file (liquid_water_run.cpp) for the scene and the study,
// which would each compile its integrators again.
#include "rotlie/models/scenes/liquid_water_experiment.hpp"
#include "rotlie/models/scenes/liquid_water_nvt.hpp"

namespace rotlie::runs {

models::liquid_water_run_result liquid_water_runs(const models::liquid_water_run_options& o, const models::rigid_bodies_state<double>& start,
                                                  const models::liquid_water_progress& progress);

models::liquid_water_nvt_result liquid_water_nvt_run(const models::liquid_water_run_options& o, const models::liquid_water_nvt_options& nvt,
                                                     const models::rigid_bodies_state<double>& start, const models::liquid_water_progress& progress);

}  // namespace rotlie::runs
