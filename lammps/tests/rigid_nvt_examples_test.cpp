// SPDX-License-Identifier: GPL-2.0-or-later
// LAMMPS's own input with fix rigid/nvt/small (package lammps-examples, found where
// lammps/bench/rigid_examples.py finds the others): deposit/in.deposit.molecule.rigid-nvt-small, 100
// dimers dropped one every 100 steps onto a Langevin-thermostatted substrate, each a rigid body of the
// thermostatted fix from the step it appears on (10,000 steps, lj units). Run as written with LAMMPS's
// rigid/nvt/small and with rigid/sier2/nvt/small in its place, each twice:
//  - as written: both count the degrees of freedom at the run's setup, when there is no body yet, so
//    neither thermostats the dimers (rigid/nvt/small skips its chains without degrees of freedom): the
//    dimers keep the heat of their fall; every deposit succeeds (550 atoms);
//  - with `fix_modify 1 dynamic/dof yes`, the count follows the deposits and the chains hold the dimers
//    at the target 0.1 (the thermo temperature is that of the dimers' atoms, 5 degrees of freedom each).
// rigid/sier4/nvt/small refuses the input: its fix nve on the substrate would move atoms by whole steps
// between SIER4's inner force evaluations.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "skip.hpp"

#include "lmp_rotlie_runner.hpp"
#include "thermo_rows.hpp"

BOOST_AUTO_TEST_SUITE(rigid_nvt_examples_test)

using namespace rotlie_lammps_test;

BOOST_AUTO_TEST_CASE(deposit_example_runs_with_the_sier_nvt_style) {
  const fs::path folder = fs::path(ROTLIE_LAMMPS_EXAMPLES) / "deposit";
  const fs::path input = folder / "in.deposit.molecule.rigid-nvt-small";
  if (!fs::exists(input)) {
    rotlie::test::skip("no LAMMPS examples at " + folder.string() + " (Debian: lammps-examples)");
    return;
  }
  scratch d("deposit_nvt");
  fs::copy_file(folder / "molecule.dimer", d.dir / "molecule.dimer");
  const std::string text = file_text(input);
  const std::string fix = "fix\t\t1 addatoms rigid/nvt/small molecule temp 0.1 0.1 0.1 mol dimer\n";
  BOOST_REQUIRE_MESSAGE(text.find(fix) != std::string::npos, "the installed example differs from LAMMPS 29 Sep 2021's");
  auto with = [&](const std::string& style, bool dynamic) {
    std::string t = text, line = fix;
    line.replace(line.find("rigid/nvt/small"), std::string("rigid/nvt/small").size(), style);
    t.replace(t.find(fix), fix.size(), line + (dynamic ? "fix_modify\t1 dynamic/dof yes\n" : ""));
    return t;
  };
  struct outcome {
    double atoms, temperature;  // at the end; the mean over steps 5000 to 10000
  };
  auto run = [&](const std::string& style, bool dynamic) {
    BOOST_REQUIRE_MESSAGE(d.run("in.deposit", with(style, dynamic)) == 0, d.output);
    const auto blocks = thermo_blocks(d.output);
    BOOST_REQUIRE(blocks.size() == 1u);
    const auto step = blocks[0].column("Step"), T = blocks[0].column("Temp");
    std::vector<double> late;
    for (std::size_t k = 0; k < step.size(); ++k)
      if (step[k] >= 5000) late.push_back(T[k]);
    BOOST_REQUIRE(late.size() == 51u);
    const outcome o{blocks[0].column("Atoms").back(), mean(late)};
    BOOST_TEST_MESSAGE(style << (dynamic ? " with dynamic/dof yes" : " as written") << ": " << o.atoms
                             << " atoms at step 10000, mean temperature of the dimers over steps 5000-10000 " << o.temperature);
    return o;
  };
  const outcome stock = run("rigid/nvt/small", false), sier2 = run("rigid/sier2/nvt/small", false);
  BOOST_TEST(stock.atoms == 550);
  BOOST_TEST(sier2.atoms == 550, "every deposit succeeds, as under rigid/nvt/small");
  BOOST_TEST(std::abs(sier2.temperature / stock.temperature - 1) < 0.15, "the same unthermostatted dimers");
  BOOST_TEST(sier2.temperature > 0.2, "no chain acts: the dimers stay far above the target 0.1");
  const outcome stock_dynamic = run("rigid/nvt/small", true), sier2_dynamic = run("rigid/sier2/nvt/small", true);
  BOOST_TEST(std::abs(stock_dynamic.temperature - 0.1) < 0.02);
  BOOST_TEST(std::abs(sier2_dynamic.temperature - 0.1) < 0.02, "the chains hold the dimers at the target");
  BOOST_TEST(std::abs(sier2_dynamic.atoms - stock_dynamic.atoms) < 0.1 * stock_dynamic.atoms);
  // SIER4: refused, in one line
  const int status = d.run("in.deposit", with("rigid/sier4/nvt/small", false));
  BOOST_TEST(status != 0);
  BOOST_TEST(d.output.find("ERROR: Fix rigid/sier4/nvt/small: fix 3 (nve) also integrates atoms") != std::string::npos, d.output);
}

// LAMMPS's 2-d micelle (micelle/in.micelle-rigid): its thermostatted stage, `fix rigid ... langevin 0.45
// 0.45 0.5 112211` with enforce2d, run with rigid/sier2/small's langevin instead, 2000 steps of 0.005.
// In 2-d the O-step acts on vx, vy and the rotation about z only: the atoms' z kinetic energy must stay
// at round-off (under LAMMPS's own rigid langevin it grows to 1.9e6, see README.md), and the bodies'
// translational and rotational temperatures at the O-stage (f_5[1], f_5[2]; 2 and 1 degrees of freedom
// a body) must average 0.45 within 10 % over the last 1000 steps (150 bodies: 5 % a sample).
BOOST_AUTO_TEST_CASE(micelle_langevin_stage_in_2d) {
  const fs::path folder = fs::path(ROTLIE_LAMMPS_EXAMPLES) / "micelle";
  if (!fs::exists(folder / "in.micelle-rigid")) {
    rotlie::test::skip("no LAMMPS examples at " + folder.string() + " (Debian: lammps-examples)");
    return;
  }
  scratch d("micelle_langevin");
  fs::copy_file(folder / "data.micelle", d.dir / "data.micelle");
  const std::string text = file_text(folder / "in.micelle-rigid");
  const std::string stage = "fix\t\t5 solute rigid molecule langevin 0.45 0.45 0.5 112211\nfix\t\t4 all enforce2d\nrun\t\t500\n";
  BOOST_REQUIRE_MESSAGE(text.find(stage) != std::string::npos, "the installed example differs from LAMMPS 29 Sep 2021's");
  const std::string input = text.substr(0, text.find(stage)) +
                            "fix\t\t5 solute rigid/sier2/small molecule langevin 0.45 0.45 0.5 112211\nfix\t\t4 all enforce2d\n"
                            "variable vzz atom 0.5*mass*vz*vz\ncompute kz all reduce sum v_vzz\n"
                            "thermo_style custom step temp c_kz f_5[1] f_5[2]\nthermo 10\nrun 2000\n";
  BOOST_REQUIRE_MESSAGE(d.run("in.micelle", input) == 0, d.output);
  const auto blocks = thermo_blocks(d.output);
  BOOST_REQUIRE(!blocks.empty());
  const auto& b = blocks.back();
  const auto step = b.column("Step"), kz = b.column("c_kz"), Tt = b.column("f_5[1]"), Tr = b.column("f_5[2]");
  std::vector<double> late_t, late_r;
  double largest_kz = 0;
  for (std::size_t k = 0; k < step.size(); ++k) {
    largest_kz = std::max(largest_kz, kz[k]);
    if (step[k] >= 1000 + step.front()) late_t.push_back(Tt[k]), late_r.push_back(Tr[k]);
  }
  BOOST_REQUIRE(late_t.size() > 90u);
  BOOST_TEST_MESSAGE("micelle, rigid/sier2/small langevin 0.45 in 2-d: largest z kinetic energy " << largest_kz
                                                                                                  << "; translational and rotational temperatures "
                                                                                                  << mean(late_t) << ", " << mean(late_r));
  BOOST_TEST(largest_kz < 1e-15);
  BOOST_TEST(std::abs(mean(late_t) / 0.45 - 1) < 0.1);
  BOOST_TEST(std::abs(mean(late_r) / 0.45 - 1) < 0.1);
}

BOOST_AUTO_TEST_SUITE_END()
