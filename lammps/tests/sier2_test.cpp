// SPDX-License-Identifier: GPL-2.0-or-later
// fix rigid/sier2/small on 216 rigid TIP3P molecules (lj/cut/coul/dsf), 200 steps of 1 fs, against
// two independent integrations of the same map: LAMMPS's own fix rigid/nve/small (NO_SQUISH, whose
// planar rotations are ABCBA2:ABC in rotlie's axis order) for `rotor ABCBA2:ABC`, and rotlie's own
// liquid-water scene integrated by its SIER2 for the default exact rotor. Agreement is to round-off
// growth: the two sides round differently (quaternions against rotation matrices; LAMMPS's neighbour
// sums against rotlie's), and the liquid amplifies a difference by about e per 10 fs.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(sier2_test)

using namespace rotlie_lammps_test;

BOOST_AUTO_TEST_CASE(rotor_abcba2_abc_reproduces_rigid_nve_small) {
  const auto start = liquid_start(216);
  scratch d("abc");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  auto run = [&](const std::string& fix) {
    const std::string input = water_head + lammps_water_pair_lines(start.w) + "fix r all " + fix + "\ntimestep 1.0\nthermo 100\nrun 200\n" + final_dump;
    BOOST_REQUIRE_MESSAGE(d.run("in.water", input) == 0, d.output);
    return read_lammps_dump(d.dir / "final.dump");
  };
  const auto nve = run("rigid/nve/small molecule");
  const auto abc = run("rigid/sier2/small molecule rotor ABCBA2:ABC");
  const auto cba = run("rigid/sier2/small molecule rotor ABCBA2:CBA");
  BOOST_REQUIRE(nve.size() == 3 * 216u);
  const double same = largest_distance(abc, nve), other = largest_distance(cba, nve);
  BOOST_TEST_MESSAGE("after 200 steps of 1 fs, largest site distance to rigid/nve/small: rotor ABCBA2:ABC " << same
                                                                                                          << " Å, rotor ABCBA2:CBA " << other << " Å");
  BOOST_TEST(same < 1e-8, "the same map: round-off growth only");
  BOOST_TEST(other > 1e3 * same, "ABCBA2:CBA is another map (O(h³) per step): the comparison can tell maps apart");
}

BOOST_AUTO_TEST_CASE(sier2_equals_rotlie_own_liquid_water_sier2) {
  std::string output;
  const double worst = largest_distance_to_rotlie("sier2", "fix r all rigid/sier2/small molecule", "SIER2", 200, output);
  BOOST_REQUIRE_MESSAGE(std::isfinite(worst), output);
  BOOST_TEST_MESSAGE("after 200 steps of 1 fs, largest site distance of rigid/sier2/small (exact rotor) to rotlie's SIER2: " << worst << " Å");
  BOOST_TEST(worst < 1e-8, "the same integrator on both sides: round-off growth only");
}

BOOST_AUTO_TEST_SUITE_END()
