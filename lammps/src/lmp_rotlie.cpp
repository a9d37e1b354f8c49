// SPDX-License-Identifier: GPL-2.0-or-later
// lmp_rotlie: LAMMPS with rotlie's fix styles (rigid/sier2/small, rigid/sier4/small). The command
// line is LAMMPS's own (-in, -var, -log, -echo, -screen, ...); under mpirun it runs on every rank.
#include <mpi.h>

#include "input.h"
#include "lammps.h"
#include "register_styles.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  rotlie::lammps::register_styles(lmp);
  lmp->input->file();
  delete lmp;
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return 0;
}
