// SPDX-License-Identifier: GPL-2.0-or-later
// fix rigid/sier4/small on 1 and 2 MPI ranks (mpirun; skipped without it): the same trajectory to
// round-off growth, with bodies and atoms crossing between the ranks' domains and neighbour lists
// rebuilt inside steps (neigh_modify every 1 delay 0 check yes).
#include <boost/test/unit_test.hpp>

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(ranks_and_restart_test)

using namespace rotlie_lammps_test;

BOOST_AUTO_TEST_CASE(one_and_two_ranks_agree) {
  if (!have_mpirun()) {
    BOOST_TEST_MESSAGE("skipped: no mpirun");
    return;
  }
  const auto start = liquid_start(216);
  scratch d("ranks");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string input = water_head + lammps_water_pair_lines(start.w) +
                            "fix r all rigid/sier4/small molecule\ntimestep 1.0\nthermo 100\nrun 100\n" + final_dump;
  BOOST_REQUIRE_MESSAGE(d.run("in.water", input, 1) == 0, d.output);
  const auto one = read_lammps_dump(d.dir / "final.dump");
  BOOST_REQUIRE_MESSAGE(d.run("in.water", input, 2) == 0, d.output);
  const auto two = read_lammps_dump(d.dir / "final.dump");
  BOOST_REQUIRE(one.size() == 3 * 216u);
  const double worst = largest_distance(one, two);
  BOOST_TEST_MESSAGE("after 100 SIER4 steps of 1 fs, largest site distance between 1 and 2 ranks: " << worst << " Å");
  BOOST_TEST(worst < 1e-8, "the same integration; sums in another order only");
}

BOOST_AUTO_TEST_SUITE_END()
