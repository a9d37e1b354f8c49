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

BOOST_AUTO_TEST_SUITE_END()
