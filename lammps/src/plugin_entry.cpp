// SPDX-License-Identifier: GPL-2.0-or-later
// The shared module rotlieplugin.so: the fix styles for a LAMMPS that did not start as lmp_rotlie.
//   rotlie_lammps_register(lmp)   registers them into a running instance (the handle of the library
//                                 interface): the loader for stock lmp's `python` command and for the
//                                 `lammps` Python module (python/rotlie_lammps.py.in)
//   lammpsplugin_init(...)        the entry of LAMMPS's PLUGIN package (`plugin load rotlieplugin.so`),
//                                 for LAMMPS builds that have it (Debian's does not: built, not run here)
#include "lammps.h"
#include "lammpsplugin.h"
#include "register_styles.h"
#include "version.h"

extern "C" {

__attribute__((visibility("default"))) int rotlie_lammps_register(void* lmp) {
  if (!lmp) return 1;
  rotlie::lammps::register_styles(static_cast<LAMMPS_NS::LAMMPS*>(lmp));
  return 0;
}

static void* create_sier2(void* lmp, int narg, char** arg) {
  return rotlie::lammps::create_sier2(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg);
}
static void* create_sier4(void* lmp, int narg, char** arg) {
  return rotlie::lammps::create_sier4(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg);
}

__attribute__((visibility("default"))) void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  auto reg = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin{};
  plugin.version = LAMMPS_VERSION;  // the PLUGIN package refuses another version itself
  plugin.style = "fix";
  plugin.author = "rotlie";
  plugin.handle = handle;
  plugin.name = "rigid/sier2/small";
  plugin.info = "rotlie: SIER2 (Strang-TV) on rigid/small bodies, keyword rotor";
  plugin.creator.v2 = &create_sier2;
  reg(&plugin, lmp);
  plugin.name = "rigid/sier4/small";
  plugin.info = "rotlie: SIER4 (PEFRL-TV, 4 force evaluations per step) on rigid/small bodies, keyword rotor";
  plugin.creator.v2 = &create_sier4;
  reg(&plugin, lmp);
}

}  // extern "C"
