// SPDX-License-Identifier: GPL-2.0-or-later
// lammps/tools/log_columns.py on a real LAMMPS log: two runs (two thermo blocks with different columns)
// of rigid/sier2/nvt/small on the water start. The CSV must hold every thermo row of both blocks, and
// its values must equal those LAMMPS writes itself, by another route, with fix print.
#include <boost/test/unit_test.hpp>

#include <cstdlib>

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(log_columns_test)

using namespace rotlie_lammps_test;

namespace {

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream fields(line);
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

BOOST_AUTO_TEST_CASE(csv_columns_equal_lammps_own_values) {
  const auto start = liquid_start(216);
  scratch d("log_columns");
  write_lammps_water_data(d.dir / "water.data", start.w, start.s.bodies);
  const std::string input = "log log.lammps\n" + water_head + lammps_water_pair_lines(start.w) +
                            "fix r all rigid/sier2/nvt/small molecule temp 300 300 100\ntimestep 2.0\n"
                            "thermo_style custom step temp pe etotal\nthermo_modify format float %.15g\nthermo 5\n"
                            "fix p all print 5 \"$(step) $(pe:%.15g) $(etotal:%.15g)\" file printed.txt screen no\n"
                            "run 20\n"
                            "thermo_style custom step pe etotal f_r\nthermo_modify format float %.15g\n"
                            "run 10\n";
  BOOST_REQUIRE_MESSAGE(d.run("in.log", input) == 0, d.output);
  const std::string cmd = "cd '" + d.dir.string() + "' && " + ROTLIE_PYTHON3 + " '" + ROTLIE_LOG_COLUMNS +
                          "' log.lammps -o all.csv > tool.out 2>&1 && " + ROTLIE_PYTHON3 + " '" + ROTLIE_LOG_COLUMNS +
                          "' log.lammps --block -1 --columns Step,f_r -o last.csv >> tool.out 2>&1";
  BOOST_REQUIRE_MESSAGE(std::system(cmd.c_str()) == 0, file_text(d.dir / "tool.out"));
  const auto all = csv_rows(file_text(d.dir / "all.csv"));
  // header, 5 rows of the first run (steps 0 to 20), 3 of the second (20 to 30)
  BOOST_REQUIRE_EQUAL(all.size(), 1u + 5 + 3);
  const std::vector<std::string> header{"block", "Step", "Temp", "PotEng", "TotEng", "f_r"};
  BOOST_TEST(all[0] == header, boost::test_tools::per_element());
  // fix print's lines: step, pe, etotal at steps 5, 10, …, 30 (the first run's rows from step 5 on)
  std::map<long, std::pair<double, double>> printed;
  {
    std::istringstream in(file_text(d.dir / "printed.txt"));
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream w(line);
      long step;
      double pe, etotal;
      if (w >> step >> pe >> etotal) printed[step] = {pe, etotal};
    }
  }
  int compared = 0;
  for (std::size_t r = 1; r < all.size(); ++r) {
    BOOST_REQUIRE_EQUAL(all[r].size(), header.size());
    const long step = std::stol(all[r][1]);
    BOOST_TEST(all[r][0] == (r <= 5 ? "0" : "1"));
    BOOST_TEST((r <= 5 ? all[r][5].empty() : all[r][2].empty()), "a block's missing columns are empty");
    const auto it = printed.find(step);
    if (it == printed.end()) continue;
    BOOST_TEST(std::stod(all[r][3]) == it->second.first, "step " << step << " pe");
    BOOST_TEST(std::stod(all[r][4]) == it->second.second, "step " << step << " etotal");
    ++compared;
  }
  BOOST_TEST_MESSAGE("log_columns.py: " << all.size() - 1 << " rows in 2 blocks; " << compared << " rows equal to fix print's values");
  BOOST_TEST(compared >= 6);
  const auto last = csv_rows(file_text(d.dir / "last.csv"));
  BOOST_REQUIRE_EQUAL(last.size(), 4u);
  BOOST_TEST(last[0] == (std::vector<std::string>{"block", "Step", "f_r"}), boost::test_tools::per_element());
  BOOST_TEST(last[3][1] == "30");
}

BOOST_AUTO_TEST_SUITE_END()
