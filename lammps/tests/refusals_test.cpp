// SPDX-License-Identifier: GPL-2.0-or-later
// Inputs the fix styles refuse: each stops LAMMPS with exactly one ERROR: line saying why (and a
// non-zero exit), never a crash or a run.
#include <boost/test/unit_test.hpp>

#include "lmp_rotlie_runner.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/scheme_table.hpp"

BOOST_AUTO_TEST_SUITE(refusals_test)

using namespace rotlie_lammps_test;

namespace {

// The ERROR: lines of the output.
std::vector<std::string> error_lines(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  std::string line;
  while (std::getline(in, line))
    if (line.find("ERROR") != std::string::npos) lines.push_back(line);
  return lines;
}

void refused(scratch& d, const std::string& pair, const std::string& fix_and_more, const std::string& expected, int ranks = 1) {
  const int status = d.run("in.refused", water_head + pair + fix_and_more + "timestep 1.0\nrun 5\n", ranks);
  const auto errors = error_lines(d.output);
  BOOST_TEST_MESSAGE(fix_and_more.substr(0, fix_and_more.find('\n')) << " (" << ranks << " ranks) → " << (errors.empty() ? "(no error)" : errors.front()));
  BOOST_TEST(status != 0);
  BOOST_TEST(errors.size() == 1u, d.output);
  if (!errors.empty()) BOOST_TEST(errors.front().rfind("ERROR:", 0) == 0);
  if (!errors.empty()) BOOST_TEST(errors.front().find(expected) != std::string::npos, errors.front());
}

}  // namespace

BOOST_AUTO_TEST_CASE(refused_inputs_give_one_error_line) {
  // a lattice start is enough: nothing runs
  const double L = cubic_box_side<double>(216, tip3p<double>().mass, 0.9973);
  const auto s = lattice_water<double>(tip3p<double>(), 216, L, 297, 21);
  const auto w = dsf_water(L);
  scratch d("refusals");
  write_lammps_water_data(d.dir / "water.data", w, s.bodies);
  const auto pair = lammps_water_pair_lines(w);
  // a table solved for the water of Leimkuhler & Vilmart (10220/29376, 19187/29376, 1), not TIP3P's moments
  const auto lv_water = rotlie::lie::parse_moments("water");
  std::ofstream(d.dir / "lv_water.scheme") << rotlie::schemes::format_scheme_table(rotlie::runs::scheme_named("N2:BAC:2", lv_water));

  // thermostat keywords: each style's own, with values LAMMPS's rigid/small and rigid/nvt/small accept
  refused(d, pair, "fix r all rigid/sier2/small molecule temp 300 300 100\n", "keyword 'temp' is rigid/sier2/nvt/small's");
  refused(d, pair, "fix r all rigid/sier4/small molecule tparam 3 1 3\n", "keyword 'tparam' is rigid/sier4/nvt/small's");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 100 langevin 300 300 100 1\n",
          "keyword 'langevin' is rigid/sier2/small's");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule\n", "temp Tstart Tstop Tdamp is required");
  refused(d, pair, "fix r all rigid/sier4/nvt/small molecule tparam 3 1 3\n", "temp Tstart Tstop Tdamp is required");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 100\n", "langevin needs 4 values: Tstart Tstop Tperiod seed");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 0 1\n", "langevin Tperiod must be a number > 0, not '0'");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 -5 1\n", "langevin Tperiod must be a number > 0");
  refused(d, pair, "fix r all rigid/sier4/small molecule langevin 0 300 100 1\n", "langevin Tstart must be a number > 0, not '0'");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 -1 100 1\n", "langevin Tstop must be a number > 0");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 100 0\n", "langevin seed must be an integer 1 to");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 100 -7\n", "langevin seed must be an integer 1 to");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 100 1.5\n", "langevin seed must be an integer 1 to");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 hundred 1\n", "langevin Tperiod must be a number > 0, not 'hundred'");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300\n", "temp needs 3 values: Tstart Tstop Tdamp");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 0\n", "temp Tdamp must be a number > 0");
  refused(d, pair, "fix r all rigid/sier4/nvt/small molecule temp -300 300 100\n", "temp Tstart must be a number > 0");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 100 tparam 0 1 3\n", "tparam Tchain must be an integer 1 to 100");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 100 tparam 3 0 3\n", "tparam Titer must be an integer 1 to 100");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 100 tparam 3 1 4\n", "tparam Torder must be 3 or 5");
  refused(d, pair, "fix r all rigid/sier2/nvt/small molecule temp 300 300 100 tparam 3 1\n", "tparam needs 3 values");
  // barostat keywords: not implemented, LAMMPS's own fixes named
  for (const char* keyword : {"iso 1 1 100", "aniso 1 1 100", "x 1 1 100", "y 1 1 100", "z 1 1 100", "couple xyz", "pchain 10", "dilate all"})
    refused(d, pair, std::string("fix r all rigid/sier2/small molecule ") + keyword + "\n",
            "is a barostat's: a barostat around SIER's free flights is not implemented; use fix rigid/npt/small or rigid/nph/small");
  refused(d, pair, "fix r all rigid/sier4/nvt/small molecule temp 300 300 100 iso 1 1 1000\n", "use fix rigid/npt/small or rigid/nph/small");
  refused(d, pair, "fix r all rigid/sier2/small molecule langevin 300 300 100\n", "langevin needs 4 values", 2);
  refused(d, pair, "fix r all rigid/sier2/small molecule rotor\n", "rotor needs a value");
  refused(d, pair, "fix r all rigid/sier2/small molecule rotor NOPE:ABC:1\n", "NOPE");
  refused(d, pair, "fix r all rigid/sier2/small molecule rotor lv_water.scheme\n", "not for body");
  refused(d, pair, "fix r all rigid/sier2/small molecule rotor lv_water.scheme\n", "not for body", 2);
  refused(d, pair, "fix r all rigid/sier2/small molecule rotor Strang-TV\n", "TV table");
  refused(d, pair, "run_style respa 2 2\nfix r all rigid/sier2/small molecule\n", "respa");
  refused(d, pair, "fix r all rigid/sier4/small molecule\nfix n all nve\n", "also integrates atoms");
}

BOOST_AUTO_TEST_CASE(a_table_solved_for_the_bodies_is_accepted) {
  // the same kind of table, solved for TIP3P's moments by the fix itself (SCHEME:PERM:LABEL), runs
  const double L = cubic_box_side<double>(216, tip3p<double>().mass, 0.9973);
  const auto s = lattice_water<double>(tip3p<double>(), 216, L, 297, 21);
  const auto w = dsf_water(L);
  scratch d("solved");
  write_lammps_water_data(d.dir / "water.data", w, s.bodies);
  const int status = d.run("in.solved", water_head + lammps_water_pair_lines(w) +
                                            "fix r all rigid/sier2/small molecule rotor N2:BAC:2\ntimestep 1.0\nrun 5\n");
  BOOST_TEST(status == 0, d.output);
  BOOST_TEST(d.output.find("rotor N2:BAC:2") != std::string::npos, d.output);
}

BOOST_AUTO_TEST_SUITE_END()
