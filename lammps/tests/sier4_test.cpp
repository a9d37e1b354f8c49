// SPDX-License-Identifier: GPL-2.0-or-later
// fix rigid/sier4/small (one LAMMPS step = one SIER4 step, 4 force evaluations, 3 of them by the fix)
// against rotlie's own liquid-water SIER4 with the same DSF pair style (216 TIP3P, 100 steps of 1 fs,
// agreement to round-off growth), and its order: the standard deviation of the total energy over the
// same 100 fs falls as h⁴ over the window h = 2, 1, 0.5 fs (slopes 4 ± 0.4), where
// rigid/sier2/small's falls as h² (2 ± 0.2). The order is measured with lj/smooth/linear on every
// site pair (force-shifted Lennard-Jones: its force is the derivative of its energy): with
// lj/cut/coul/dsf the energy of every integrator levels off near 3e-4 kcal/mol whatever h (seen:
// the same 2.99e-4 at h = 2 and 1 fs), LAMMPS's coul/dsf approximating erfc in a way whose force is not
// exactly the derivative of its energy.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(sier4_test)

using namespace rotlie_lammps_test;

namespace {

// The standard deviation of etotal over a run of `fs` femtoseconds at step h (thermo every step).
double energy_fluctuation(scratch& d, const std::string& pair_lines, const std::string& style, double h, double fs) {
  const long steps = std::lround(fs / h);
  const std::string input = water_head + pair_lines + "fix r all " + style + " molecule\ntimestep " + lammps_number(h) +
                            "\nthermo_style custom step etotal\nthermo_modify format float %.17g\nthermo 1\nrun " + std::to_string(steps) + "\n";
  BOOST_REQUIRE_MESSAGE(d.run("in.water", input) == 0, d.output);
  std::istringstream out(d.output);
  std::string line;
  bool thermo = false;
  double s = 0, ss = 0, e0 = NAN;  // sums of E − E(0): E² itself would cancel in double
  long n = 0;
  while (std::getline(out, line)) {
    if (line.find("Step") != std::string::npos && line.find("TotEng") != std::string::npos) {
      thermo = true;
      continue;
    }
    if (line.rfind("Loop time", 0) == 0) break;
    std::istringstream row(line);
    long step;
    double e;
    if (thermo && row >> step >> e) {
      if (n == 0) e0 = e;
      e -= e0;
      s += e;
      ss += e * e;
      ++n;
    }
  }
  BOOST_REQUIRE(n == steps + 1);
  const double mean = s / static_cast<double>(n);
  return std::sqrt(std::max(0.0, ss / static_cast<double>(n) - mean * mean));
}

}  // namespace

BOOST_AUTO_TEST_CASE(sier4_equals_rotlie_own_liquid_water_sier4) {
  std::string output;
  const double worst = largest_distance_to_rotlie("sier4_same", "fix r all rigid/sier4/small molecule", "SIER4", 100, output);
  BOOST_REQUIRE_MESSAGE(std::isfinite(worst), output);
  BOOST_TEST_MESSAGE("after 100 SIER4 steps of 1 fs, largest site distance of rigid/sier4/small to rotlie's SIER4: " << worst << " Å");
  BOOST_TEST(worst < 1e-8, "the same integrator on both sides: round-off growth only");
}

BOOST_AUTO_TEST_CASE(energy_fluctuation_falls_as_h_to_the_fourth) {
  const auto start = liquid_start(216);
  scratch d("sier4");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string pair =
      "pair_style lj/smooth/linear 9\npair_coeff 1 1 0.1520725945017182 3.1506561104957425\n"
      "pair_coeff 1 2 0.0836 1.7753\npair_coeff 2 2 0.046 0.4\nneighbor 2.0 bin\nneigh_modify exclude molecule/intra all every 1 delay 0 check yes\n";
  const std::vector<double> steps = {2.0, 1.0, 0.5};
  std::vector<double> sier4, sier2;
  for (const double h : steps) {
    sier4.push_back(energy_fluctuation(d, pair, "rigid/sier4/small", h, 100));
    sier2.push_back(energy_fluctuation(d, pair, "rigid/sier2/small", h, 100));
    BOOST_TEST_MESSAGE("h = " << h << " fs: energy fluctuation SIER4 " << sier4.back() << ", SIER2 " << sier2.back() << " kcal/mol");
  }
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    const double slope4 = std::log(sier4[k] / sier4[k + 1]) / std::log(steps[k] / steps[k + 1]);
    const double slope2 = std::log(sier2[k] / sier2[k + 1]) / std::log(steps[k] / steps[k + 1]);
    BOOST_TEST_MESSAGE("h " << steps[k] << " → " << steps[k + 1] << " fs: slope SIER4 " << slope4 << ", SIER2 " << slope2);
    BOOST_TEST(std::abs(slope4 - 4) < 0.4);
    BOOST_TEST(std::abs(slope2 - 2) < 0.2);
  }
}

BOOST_AUTO_TEST_SUITE_END()
