// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// A force evaluation in the middle of a LAMMPS step, for the stages of a TV table between its first
// and last kick. It is the part of LAMMPS's Verlet::run between initial_integrate and
// final_integrate, in the same order: the neighbour decision, then communication of ghost positions
// or a re-neighbouring (pre_exchange, pbc, exchange, borders, pre_neighbor, build, post_neighbor),
// forces cleared, pre_force, pair, bonded terms, kspace, pre_reverse, the reverse communication of
// forces, and post_force of every fix. Energies and virials are not tallied (eflag = vflag = 0): they
// belong to the step's end, which LAMMPS's own evaluation computes. Atoms are not sorted here.
// neigh_modify delay and every count force evaluations (f per step), since each asks the neighbour
// decision. Time goes to LAMMPS's timer categories as Verlet's does.
namespace LAMMPS_NS {
class LAMMPS;
}

namespace rotlie::lammps {

void mid_step_forces(LAMMPS_NS::LAMMPS* lmp);

}  // namespace rotlie::lammps
