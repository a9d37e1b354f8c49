// SPDX-License-Identifier: GPL-2.0-or-later
// For version_test only: a LAMMPS instance of the installed library that claims to be VERSION
// (its public `version` string, which is what the adapter compares), into which the fix styles are
// registered as lmp_rotlie registers them. Without VERSION the instance keeps its own.
//   lammps_version_probe [VERSION]
#include <mpi.h>

#include <cstdio>

#include "lammps.h"
#include "register_styles.h"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  char name[] = "lammps_version_probe", log[] = "-log", none[] = "none", nocite[] = "-nocite";
  char* args[] = {name, log, none, nocite};
  auto* lmp = new LAMMPS_NS::LAMMPS(4, args, MPI_COMM_WORLD);
  if (argc > 1) lmp->version = argv[1];
  rotlie::lammps::register_styles(lmp);  // refuses another version: one ERROR: line, exit status 1
  std::printf("registered into LAMMPS %s (headers: %s)\n", lmp->version, rotlie::lammps::header_version());
  delete lmp;
  MPI_Finalize();
  return 0;
}
