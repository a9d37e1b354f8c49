// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// The fix styles rigid/NAME/small, one for each family of the method registry that has one
// (runs/methods.hpp: rigid/sier2/small, rigid/sier4/small, …) and its thermostatted variant
// rigid/NAME/nvt/small, added to a running LAMMPS instance's style
// map (Modify::fix_map is public), as LAMMPS's PLUGIN package does internally: no plugin support is
// needed in the LAMMPS build.
namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}

namespace rotlie::lammps {

/// The LAMMPS version (date) of the headers this adapter was compiled against.
const char* header_version();

/// The styles' creator (Modify's FixCreator signature): the style, arg[2], names the family.
LAMMPS_NS::Fix* create_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

/// Registers the styles; a LAMMPS whose version differs from header_version() is refused with one
/// ERROR: line (the classes' layout is that of the headers).
void register_styles(LAMMPS_NS::LAMMPS* lmp);

}  // namespace rotlie::lammps
