// The scenes a user can name, in the order the help lists them: the one list to extend when a scene
// is added (its entry in runs/src/scenes/NAME_scene.cpp).
#include "rotlie/runs/scenes.hpp"

namespace rotlie::runs {

scene free_water_scene();
scene dipole_field_scene();
scene liquid_water_scene();
scene spin_orbit_scene();

const std::vector<scene>& scenes() {
  static const std::vector<scene> all{free_water_scene(), dipole_field_scene(), liquid_water_scene(), spin_orbit_scene()};
  return all;
}

}  // namespace rotlie::runs
