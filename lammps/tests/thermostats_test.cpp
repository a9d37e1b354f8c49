// SPDX-License-Identifier: GPL-2.0-or-later
// The thermostats of the SIER fixes on 216 rigid TIP3P molecules (lj/cut/coul/dsf, rotlie's liquid
// start near 300 K): `langevin` of rigid/sier2/small and rigid/sier4/small (the exact O-step inside the
// step) and the Nosé–Hoover chains of rigid/sier2/nvt/small and rigid/sier4/nvt/small.
//   thermostat_ranks_test       1 and 2 MPI ranks: the same trajectory, the same noise
//   thermostat_restart_test     write_restart / read_restart continues exactly as the writing process
//   thermostat_statistics_test  the temperatures Langevin samples at 4 fs; the chains' conserved quantity
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "skip.hpp"

#include "lmp_rotlie_runner.hpp"
#include "thermo_rows.hpp"

using namespace rotlie_lammps_test;

namespace {

struct thermostatted {
  const char* fix;  ///< the fix command's words after the group
  bool chains;      ///< nvt: f_r is the chains' energy
};

const thermostatted cases[] = {
    {"rigid/sier2/small molecule langevin 300 300 100 4711", false},
    {"rigid/sier4/small molecule langevin 300 300 100 4711", false},
    {"rigid/sier2/nvt/small molecule temp 300 300 100", true},
    {"rigid/sier4/nvt/small molecule temp 300 300 100", true},
};

std::string thermo_lines(bool chains, int every) {
  return std::string("thermo_style custom step temp pe etotal") + (chains ? " f_r" : "") + "\nthermo_modify format float %.15g\nthermo " +
         std::to_string(every) + "\n";
}

// The largest relative difference between the rows of two runs' last thermo blocks (infinite when
// their shapes differ).
double largest_relative_difference(const std::string& a, const std::string& b) {
  const auto x = thermo_blocks(a), y = thermo_blocks(b);
  if (x.empty() || y.empty() || x.back().rows.size() != y.back().rows.size() || x.back().rows.empty()) return INFINITY;
  double worst = 0;
  for (std::size_t r = 0; r < x.back().rows.size(); ++r)
    for (std::size_t c = 1; c < x.back().columns.size(); ++c) {
      const double u = x.back().rows[r][c], v = y.back().rows[r][c];
      worst = std::max(worst, std::abs(u - v) / std::max(std::abs(u), 1e-300));
    }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(thermostat_ranks_test)

// 100 steps of 2 fs on 1 and 2 ranks: the bodies draw their normals by their atoms' tags and the chains
// see the kinetic energy summed over the ranks, so the two runs are the same integration, with sums in
// another order only. Round-off (1e-16) grows by about e per 10 fs in the liquid: after 200 fs about
// 1e-16 · e^20 ≈ 1e-7 relative at worst, in practice far less; a run with another seed (other noise)
// differs by ångströms (2.6 Å measured), which the tolerances (1e-6 Å, 1e-8 relative in thermo) tell apart.
BOOST_AUTO_TEST_CASE(one_and_two_ranks_agree) {
  if (!have_mpirun()) {
    rotlie::test::skip("no mpirun");
    return;
  }
  const auto start = liquid_start(216);
  scratch d("thermostat_ranks");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  for (const auto& c : cases) {
    auto input = [&](const std::string& fix) {
      return water_head + lammps_water_pair_lines(start.w) + "fix r all " + fix + "\n" + thermo_lines(c.chains, 20) +
             "timestep 2.0\nrun 100\n" + final_dump;
    };
    BOOST_REQUIRE_MESSAGE(d.run("in.water", input(c.fix), 1) == 0, d.output);
    const auto one = read_lammps_dump(d.dir / "final.dump");
    const std::string one_out = d.output;
    BOOST_REQUIRE_MESSAGE(d.run("in.water", input(c.fix), 2) == 0, d.output);
    const auto two = read_lammps_dump(d.dir / "final.dump");
    BOOST_REQUIRE(one.size() == 3 * 216u);
    const double worst = largest_distance(one, two), thermo = largest_relative_difference(one_out, d.output);
    BOOST_TEST_MESSAGE(c.fix << ": 1 against 2 ranks after 100 steps of 2 fs: largest site distance " << worst
                             << " Å, largest relative thermo difference " << thermo);
    BOOST_TEST(worst < 1e-6, c.fix);
    BOOST_TEST(thermo < 1e-8, c.fix);
    if (!c.chains) {
      // the noise is real: another seed is another trajectory
      std::string other = c.fix;
      other.replace(other.find("4711"), 4, "4712");
      BOOST_REQUIRE_MESSAGE(d.run("in.water", input(other), 2) == 0, d.output);
      const double apart = largest_distance(one, read_lammps_dump(d.dir / "final.dump"));
      BOOST_TEST_MESSAGE(c.fix << ": seed 4712 instead, largest site distance " << apart << " Å");
      BOOST_TEST(apart > 1e-2, c.fix);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(thermostat_restart_test)

// `run 50`, write_restart, `run 50` in one process against read_restart + `run 50` in a new one: the
// dumps of x and v equal to the last digit and the same thermo rows (the chains' energy f_r included).
// Langevin keeps no generator state (the noise is keyed by the step); the chains' η and v are in the file.
BOOST_AUTO_TEST_CASE(restart_continues_the_run) {
  const auto start = liquid_start(216);
  scratch d("thermostat_restart");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string neighbour = "neighbor 2.0 bin\nneigh_modify exclude molecule/intra all every 1 delay 0 check yes\n";
  for (const int ranks : {1, 2}) {
    if (ranks > 1 && !have_mpirun()) {
      rotlie::test::skip("2 ranks: no mpirun");
      continue;
    }
    for (const auto& c : {cases[0], cases[3]}) {
      const std::string fix = "fix r all " + std::string(c.fix) + "\n" + thermo_lines(c.chains, 10);
      BOOST_REQUIRE_MESSAGE(d.run("in.write", water_head + lammps_water_pair_lines(start.w) + fix +
                                                  "timestep 2.0\nrun 50\nwrite_restart half.restart\nrun 50\n" + final_state_dump,
                                  ranks) == 0,
                            d.output);
      const std::string continued = file_text(d.dir / "final.dump"), continued_out = d.output;
      BOOST_REQUIRE_MESSAGE(d.run("in.read", "read_restart half.restart\n" + neighbour + fix + "run 50\n" + final_state_dump, ranks) == 0,
                            d.output);
      const std::string restarted = file_text(d.dir / "final.dump");
      BOOST_REQUIRE(continued.size() > 3 * 216 * 6 * 17u);
      BOOST_TEST(continued == restarted, ranks << " rank(s), " << c.fix << ": the restarted run's x and v differ");
      // the thermo rows of steps 50 to 100: the continued run's last block against the restarted run's
      const auto a = thermo_blocks(continued_out), b = thermo_blocks(d.output);
      BOOST_REQUIRE(a.size() == 2u);
      BOOST_REQUIRE(b.size() == 1u);
      BOOST_TEST(a.back().rows == b.back().rows, ranks << " rank(s), " << c.fix << ": thermo rows differ");
      if (c.chains) {
        const auto e = b.back().column("f_r");
        BOOST_TEST(std::abs(e.front()) > 0, "the chains have moved by step 50: their restored energy is not zero");
        BOOST_TEST_MESSAGE(ranks << " rank(s), " << c.fix << ": f_r at step 50 (restored) " << e.front() << " kcal/mol");
      }
      BOOST_TEST_MESSAGE(ranks << " rank(s), " << c.fix << ": restart after 50 steps, 50 more: dumps identical: " << (continued == restarted));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(thermostat_statistics_test)

namespace {
constexpr double boltz = 0.0019872067;  // LAMMPS's k_B, kcal/mol/K (units real)
}

// Langevin (BAOAB with the exact free rotation) at 4 fs, friction 1/(100 fs), 300 K, on 216 molecules:
// 1 ps to forget the start, then 20 ps sampled every 40 fs. Two kinetic temperatures:
//  - in the middle of the step, just before the O-stage (the fix's vector f_r[1], f_r[2]): BAOAB's
//    momenta there are exactly Boltzmann-distributed for harmonic modes (the configurational marginal is
//    exact and the O-step's input is the A-half's), so both must be 300 K within 4 standard errors of
//    their means (by blocking) and 1 K for the librations' anharmonicity;
//  - at the step's end, 2 E/(3 N k_B) with E from compute ke/rigid and erotate/rigid, as LAMMPS's thermo
//    sees them: BAOAB's step-end momenta have variance kT (1 − (hω)²/4) for a mode of frequency ω, so
//    the translations (ω ≲ 200 cm⁻¹: below 0.5 %) must give 300 K as above, while the rotations
//    (TIP3P's librations, 500–900 cm⁻¹: (hω)²/4 = 3.5 % to 11 % at 4 fs) must sit below 300 K by 1 % to 12 %.
BOOST_AUTO_TEST_CASE(langevin_at_4_fs_samples_300_kelvin) {
  const auto start = liquid_start(216);
  scratch d("langevin_statistics");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string input = water_head + lammps_water_pair_lines(start.w) +
                            "fix r all rigid/sier2/small molecule langevin 300 300 100 2024\n"
                            "compute kt all ke/rigid r\ncompute kr all erotate/rigid r\n"
                            "thermo_style custom step temp pe c_kt c_kr f_r[1] f_r[2]\nthermo_modify format float %.15g\nthermo 10\n"
                            "timestep 4.0\nrun 250\nrun 5000\n";
  BOOST_REQUIRE_MESSAGE(d.run("in.water", input) == 0, d.output);
  const auto blocks = thermo_blocks(d.output);
  BOOST_REQUIRE(blocks.size() == 2u);
  const double dof = 3 * 216;
  auto temperatures = [&](const char* column, double scale) {
    std::vector<double> T;
    for (const double x : blocks.back().column(column)) T.push_back(scale * x);
    return T;
  };
  struct measured {
    const char* what;
    std::vector<double> T;
  };
  const measured series[] = {{"translational, step's middle (f_r[1])", temperatures("f_r[1]", 1)},
                             {"rotational, step's middle (f_r[2])", temperatures("f_r[2]", 1)},
                             {"translational, step's end (ke/rigid)", temperatures("c_kt", 2 / (dof * boltz))},
                             {"rotational, step's end (erotate/rigid)", temperatures("c_kr", 2 / (dof * boltz))}};
  double T[4], se[4];
  for (int k = 0; k < 4; ++k) {
    BOOST_REQUIRE(series[k].T.size() == 501u);
    T[k] = mean(series[k].T), se[k] = blocked_error(series[k].T);
    BOOST_TEST_MESSAGE("rigid/sier2/small langevin at 4 fs, " << series[k].what << ": " << T[k] << " K ± " << se[k]
                                                              << " (standard error of the mean, 10 blocks)");
  }
  for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(T[k] - 300) < 4 * se[k] + 1, series[k].what << ": " << T[k] << " ± " << se[k] << " K");
  const double deficit = 1 - T[3] / 300;
  BOOST_TEST_MESSAGE("the step-end rotational temperature is " << 100 * deficit << " % below 300 K (BAOAB's (hω)²/4 for the librations)");
  BOOST_TEST(deficit > 0.01);
  BOOST_TEST(deficit < 0.12);
}

// The chains' conserved quantity: rigid/sier2/nvt/small at 2 fs, Tdamp 100 fs, 2000 steps (4 ps).
// etotal + f_r must not drift and must fluctuate far less than etotal does (the chains move energy in
// and out of the bodies: etotal alone wanders by the thermostat's exchanges).
BOOST_AUTO_TEST_CASE(the_chains_conserved_quantity_stays_bounded) {
  const auto start = liquid_start(216);
  scratch d("nhc_conserved");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  for (const char* style : {"rigid/sier2/nvt/small", "rigid/sier4/nvt/small"}) {
    const int steps = std::string(style).find("sier4") != std::string::npos ? 500 : 2000;
    const std::string input = water_head + lammps_water_pair_lines(start.w) + "fix r all " + style + " molecule temp 300 300 100\n" +
                              "variable conserved equal etotal+f_r\n"
                              "thermo_style custom step temp pe etotal f_r v_conserved econserve\nthermo_modify format float %.15g\nthermo 10\n"
                              "timestep 2.0\nrun " + std::to_string(steps) + "\n";
    BOOST_REQUIRE_MESSAGE(d.run("in.water", input) == 0, d.output);
    const auto blocks = thermo_blocks(d.output);
    BOOST_REQUIRE(blocks.size() == 1u);
    const auto H = blocks.back().column("v_conserved"), E = blocks.back().column("TotEng"), econserve = blocks.back().column("Econserve");
    BOOST_REQUIRE(H.size() > 10u);
    auto spread = [](const std::vector<double>& x) { return *std::max_element(x.begin(), x.end()) - *std::min_element(x.begin(), x.end()); };
    const double drift = H.back() - H.front();
    BOOST_TEST_MESSAGE(style << " at 2 fs, " << steps << " steps: etotal + f_r spread " << spread(H) << ", drift " << drift
                             << " kcal/mol; etotal spread " << spread(E) << " kcal/mol; mean temperature "
                             << mean(blocks.back().column("Temp")) << " K");
    BOOST_TEST(spread(H) < 0.1 * spread(E), style);
    BOOST_TEST(std::abs(drift) < 0.05 * spread(E), style);
    // thermo's econserve (etotal + the ecouple of the fixes) is the same quantity
    for (std::size_t k = 0; k < H.size(); ++k) BOOST_TEST(std::abs(econserve[k] - H[k]) < 1e-9 * std::abs(H[k]));
  }
}

BOOST_AUTO_TEST_SUITE_END()
