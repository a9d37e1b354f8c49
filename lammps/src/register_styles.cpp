// SPDX-License-Identifier: GPL-2.0-or-later
#include "register_styles.h"

#include <cstring>
#include <string>

#include "error.h"
#include "fix_rigid_sier_small.h"
#include "lammps.h"
#include "modify.h"
#include "rotlie/runs/methods.hpp"
#include "version.h"

namespace rotlie::lammps {
using namespace LAMMPS_NS;

Fix* create_fix(LAMMPS* lmp, int narg, char** arg) { return new FixRigidSierSmall(lmp, narg, arg); }

const char* header_version() { return LAMMPS_VERSION; }

void register_styles(LAMMPS* lmp) {
  if (std::strcmp(lmp->version, LAMMPS_VERSION) != 0)
    lmp->error->all(FLERR, std::string("rotlie's fix styles were built against LAMMPS ") + LAMMPS_VERSION + ", this is LAMMPS " +
                               lmp->version + ": rebuild lammps/ with this version's headers");
  for (const auto& f : runs::method_families())
    if (f.lammps_style) {
      // rigid/NAME/small (NVE, or langevin) and rigid/NAME/nvt/small (Nose-Hoover chains)
      (*lmp->modify->fix_map)[runs::lammps_style_of(f)] = &create_fix;
      (*lmp->modify->fix_map)[nvt_style_of(runs::lammps_style_of(f))] = &create_fix;
    }
}

}  // namespace rotlie::lammps
