// SPDX-License-Identifier: GPL-2.0-or-later
#include "mid_step_forces.h"

#include <cstring>

#include "angle.h"
#include "atom.h"
#include "atom_vec.h"
#include "bond.h"
#include "comm.h"
#include "dihedral.h"
#include "domain.h"
#include "force.h"
#include "improper.h"
#include "kspace.h"
#include "lammps.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "timer.h"

namespace rotlie::lammps {
namespace {

using namespace LAMMPS_NS;

void clear_forces(Atom* atom, bool newton, int includegroup) {
  const bool torque = atom->torque_flag != 0, extra = atom->avec->forceclearflag != 0;
  auto clear = [&](int first, int n) {
    const size_t nbytes = sizeof(double) * static_cast<size_t>(n);
    if (!nbytes) return;
    std::memset(&atom->f[first][0], 0, 3 * nbytes);
    if (torque) std::memset(&atom->torque[first][0], 0, 3 * nbytes);
    if (extra) atom->avec->force_clear(first, nbytes);
  };
  if (includegroup == 0) {
    clear(0, atom->nlocal + (newton ? atom->nghost : 0));
  } else {
    clear(0, atom->nfirst);
    if (newton) clear(atom->nlocal, atom->nghost);
  }
}

}  // namespace

void mid_step_forces(LAMMPS* lmp) {
  Atom* atom = lmp->atom;
  Domain* domain = lmp->domain;
  Comm* comm = lmp->comm;
  Force* force = lmp->force;
  Modify* modify = lmp->modify;
  Neighbor* neighbor = lmp->neighbor;
  Timer* timer = lmp->timer;
  const int eflag = 0, vflag = 0;
  timer->stamp(Timer::MODIFY);  // the stages before this evaluation

  if (neighbor->decide() == 0) {
    comm->forward_comm();
    timer->stamp(Timer::COMM);
  } else {
    modify->pre_exchange();
    timer->stamp(Timer::MODIFY);
    if (domain->triclinic) domain->x2lamda(atom->nlocal);
    domain->pbc();
    if (domain->box_change) {
      domain->reset_box();
      comm->setup();
      if (neighbor->style) neighbor->setup_bins();
    }
    timer->stamp();
    comm->exchange();
    comm->borders();
    if (domain->triclinic) domain->lamda2x(atom->nlocal + atom->nghost);
    timer->stamp(Timer::COMM);
    modify->pre_neighbor();
    timer->stamp(Timer::MODIFY);
    neighbor->build(1);
    timer->stamp(Timer::NEIGH);
    modify->post_neighbor();
    timer->stamp(Timer::MODIFY);
  }

  clear_forces(atom, force->newton != 0, neighbor->includegroup);
  timer->stamp();
  modify->pre_force(vflag);
  timer->stamp(Timer::MODIFY);
  if (force->pair && force->pair->compute_flag) {
    force->pair->compute(eflag, vflag);
    timer->stamp(Timer::PAIR);
  }
  if (atom->molecular != Atom::ATOMIC) {
    if (force->bond) force->bond->compute(eflag, vflag);
    if (force->angle) force->angle->compute(eflag, vflag);
    if (force->dihedral) force->dihedral->compute(eflag, vflag);
    if (force->improper) force->improper->compute(eflag, vflag);
    timer->stamp(Timer::BOND);
  }
  if (force->kspace && force->kspace->compute_flag) {
    force->kspace->compute(eflag, vflag);
    timer->stamp(Timer::KSPACE);
  }
  modify->pre_reverse(eflag, vflag);
  if (force->newton) {
    comm->reverse_comm();
    timer->stamp(Timer::COMM);
  }
  modify->post_force(vflag);
  timer->stamp(Timer::MODIFY);
}

}  // namespace rotlie::lammps
