// SPDX-License-Identifier: GPL-2.0-or-later
// The shared module rotlieplugin.so: the fix styles for a LAMMPS that did not start as lmp_rotlie.
//   rotlie_lammps_register(lmp)   registers them into a running instance (the handle of the library
//                                 interface): the loader for stock lmp's `python` command and for the
//                                 `lammps` Python module (python/rotlie_lammps.py.in)
//   lammpsplugin_init(...)        the entry of LAMMPS's PLUGIN package (`plugin load rotlieplugin.so`),
//                                 for LAMMPS builds that have it (Debian's does not: built, not run here)
#include <string>
#include <vector>

#include "lammps.h"
#include "lammpsplugin.h"
#include "fix_rigid_sier_small.h"
#include "register_styles.h"
#include "rotlie/runs/methods.hpp"
#include "version.h"

extern "C" {

__attribute__((visibility("default"))) int rotlie_lammps_register(void* lmp) {
  if (!lmp) return 1;
  rotlie::lammps::register_styles(static_cast<LAMMPS_NS::LAMMPS*>(lmp));
  return 0;
}

static void* create_fix(void* lmp, int narg, char** arg) {
  return rotlie::lammps::create_fix(static_cast<LAMMPS_NS::LAMMPS*>(lmp), narg, arg);
}

__attribute__((visibility("default"))) void lammpsplugin_init(void* lmp, void* handle, void* regfunc) {
  auto reg = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  lammpsplugin_t plugin{};
  plugin.version = LAMMPS_VERSION;  // the PLUGIN package refuses another version itself
  plugin.style = "fix";
  plugin.author = "rotlie";
  plugin.handle = handle;
  for (const auto& f : rotlie::runs::method_families()) {
    if (!f.lammps_style) continue;
    // the registry's rows live as long as the program: their text can be handed to LAMMPS
    static std::vector<std::string> texts;
    texts.reserve(4 * rotlie::runs::method_families().size());  // no reallocation: LAMMPS keeps the pointers
    const std::string name = rotlie::runs::lammps_style_of(f);
    const std::string what = f.name + " (" + f.tv_table + ", " + std::to_string(f.force_evaluations()) + " force evaluations per step) on rigid/small bodies";
    plugin.name = texts.emplace_back(name).c_str();
    plugin.info = texts.emplace_back("rotlie: " + what + ", keywords rotor, langevin").c_str();
    plugin.creator.v2 = &create_fix;
    reg(&plugin, lmp);
    plugin.name = texts.emplace_back(rotlie::lammps::nvt_style_of(name)).c_str();
    plugin.info = texts.emplace_back("rotlie: " + what + " with Nose-Hoover chains, keywords rotor, temp, tparam").c_str();
    reg(&plugin, lmp);
  }
}

}  // extern "C"
