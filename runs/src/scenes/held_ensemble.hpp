#pragma once
// An ensemble scene (free water, a dipole in a field) held as md_simulation's run: every run's state
// from scene.initial(seed, run), stepped by the one composition the scene's run function builds,
// step by step as models::integrate steps it. Instantiated once per scalar in held_ensembles.cpp.
#include <memory>
#include <vector>

#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/models/scenes/dipole_field.hpp"
#include "rotlie/models/scenes/free_water.hpp"
#include "rotlie/runs/md_simulation.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::runs::scene_support {

/// The ensemble of o's runs; with prepare_forces, each start's forces evaluated first (as
/// run_dipole_field does: V at the start).
template <class Scene>
std::unique_ptr<held_md_run> held_ensemble(const Scene& scene, const models::md_run_options& o, bool prepare_forces);

extern template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<double>&, const models::md_run_options&, bool);
extern template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<long double>&, const models::md_run_options&, bool);
extern template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<quad>&, const models::md_run_options&, bool);
extern template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<double>&, const models::md_run_options&, bool);
extern template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<long double>&, const models::md_run_options&, bool);
extern template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<quad>&, const models::md_run_options&, bool);

}  // namespace rotlie::runs::scene_support
