// SPDX-License-Identifier: GPL-2.0-or-later
// fix rigid/sier4/small on 1, 2 and 4 MPI ranks (mpirun; skipped without it): the same trajectory to
// round-off growth, with bodies and atoms crossing between the ranks' domains and neighbour lists
// rebuilt inside steps (neigh_modify every 1 delay 0 check yes). And write_restart/read_restart:
// a new process that reads the restart file written after 50 steps continues exactly as the
// writing process does with a second `run 50` (positions and velocities equal to the last bit, on 1
// and on 2 ranks). Like fix rigid/small, the fix sets its bodies up from the atoms at each run's
// start (reinit yes), so the comparison is with a second run, not with one run of 100 steps.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(ranks_and_restart_test)

using namespace rotlie_lammps_test;

BOOST_AUTO_TEST_CASE(one_two_and_four_ranks_agree) {
  if (!have_mpirun()) {
    rotlie::test::skip("no mpirun");
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
  // 4 ranks (more than this machine's cores: oversubscribed), sub-domains narrower than the cutoff
  BOOST_REQUIRE_MESSAGE(d.run("in.water", input, 4) == 0, d.output);
  const auto four = read_lammps_dump(d.dir / "final.dump");
  const double worst4 = largest_distance(one, four);
  BOOST_TEST_MESSAGE("after 100 SIER4 steps of 1 fs, largest site distance between 1 and 4 ranks: " << worst4 << " Å");
  BOOST_TEST(worst4 < 1e-8, "the same integration; sums in another order only");
}

BOOST_AUTO_TEST_CASE(restart_continues_bit_identically) {
  const auto start = liquid_start(216);
  scratch d("restart");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string& dump = final_state_dump;
  auto text = [&](const char* file) { return file_text(d.dir / file); };
  // the lines liquid_water's pair lines add beyond what a restart file stores (neighbour settings)
  const std::string neighbour = "neighbor 2.0 bin\nneigh_modify exclude molecule/intra all every 1 delay 0 check yes\n";
  for (const int ranks : {1, 2}) {
    if (ranks > 1 && !have_mpirun()) {
      rotlie::test::skip("2 ranks: no mpirun");
      continue;
    }
    const std::string fix = "fix r all rigid/sier4/small molecule\n";
    BOOST_REQUIRE_MESSAGE(d.run("in.write", water_head + lammps_water_pair_lines(start.w) + fix +
                                                "timestep 1.0\nrun 50\nwrite_restart half.restart\nrun 50\n" + dump, ranks) == 0,
                          d.output);
    const std::string continued = text("final.dump");
    BOOST_REQUIRE_MESSAGE(d.run("in.read", "read_restart half.restart\n" + neighbour + fix + "run 50\n" + dump, ranks) == 0, d.output);
    const std::string restarted = text("final.dump");
    BOOST_REQUIRE(continued.size() > 3 * 216 * 6 * 17u);
    // the dumps' headers hold the same step and box; every digit of x and v must agree
    BOOST_TEST(continued == restarted, ranks << " rank(s): the restarted run's positions and velocities differ from the continued run's");
    BOOST_TEST_MESSAGE(ranks << " rank(s): restart after 50 SIER4 steps, 50 more: dumps of x and v identical: " << (continued == restarted));
  }
}

BOOST_AUTO_TEST_SUITE_END()
