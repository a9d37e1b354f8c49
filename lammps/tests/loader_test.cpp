// SPDX-License-Identifier: GPL-2.0-or-later
// Stock lmp (Debian's, with its PYTHON package) loads the fix styles through its `python` command
// and the loader rotlie_lammps.py (rotlieplugin.so): 50 SIER4 steps of 216 TIP3P end in the same
// positions and velocities, to the last digit, as lmp_rotlie's, on 1 and 2 ranks. So does a Python
// program that drives LAMMPS through Debian's `lammps` module (python3-lammps) and loads the styles
// with rotlie_lammps.load_into (skipped where the module is not installed). A module that fails to
// load is named with the reason, and a handle that is not one (an integer) is refused.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "lmp_rotlie_runner.hpp"

BOOST_AUTO_TEST_SUITE(loader_test)

using namespace rotlie_lammps_test;

namespace {

// 216 lattice TIP3P written into d's folder; the input lines after the data file: DSF pairs, 50 SIER4
// steps of 1 fs, and the final positions and velocities dumped to the last digit.
std::string sier4_water_run(const scratch& d) {
  const double L = cubic_box_side<double>(216, tip3p<double>().mass, 0.9973);
  const auto s = lattice_water<double>(tip3p<double>(), 216, L, 297, 21);
  const auto w = dsf_water(L);
  write_lammps_water_data(d.dir / "water.data", w, s.bodies);
  return lammps_water_pair_lines(w) + "fix r all rigid/sier4/small molecule\ntimestep 1.0\nrun 50\n" + final_state_dump;
}

}  // namespace

BOOST_AUTO_TEST_CASE(stock_lmp_with_the_python_loader_runs_the_styles) {
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) {
    rotlie::test::skip("no stock lmp");
    return;
  }
  scratch d("loader");
  const std::string body = sier4_water_run(d);
  const std::string load = std::string("python rotlie_load input 1 SELF format p file ") + ROTLIE_LAMMPS_LOADER + "\npython rotlie_load invoke\n";
  auto text = [&] { return file_text(d.dir / "final.dump"); };
  for (const int ranks : {1, 2}) {
    if (ranks > 1 && !have_mpirun()) {
      rotlie::test::skip("2 ranks: no mpirun");
      continue;
    }
    BOOST_REQUIRE_MESSAGE(d.run("in.launcher", water_head + body, ranks) == 0, d.output);
    const std::string launcher = text();
    BOOST_REQUIRE_MESSAGE(d.run("in.stock", water_head + load + body, ranks, "", "lmp") == 0, d.output);
    const std::string stock = text();
    BOOST_TEST(launcher.size() > 3 * 216 * 6 * 17u);
    BOOST_TEST(launcher == stock, ranks << " rank(s): stock lmp with the loader differs from lmp_rotlie");
    BOOST_TEST_MESSAGE(ranks << " rank(s): stock lmp + python loader, 50 SIER4 steps: dump equal to lmp_rotlie's: " << (launcher == stock));
  }
}

BOOST_AUTO_TEST_CASE(the_lammps_python_module_with_the_loader_runs_the_styles) {
  const std::string python = ROTLIE_LAMMPS_PYTHON;
  if (std::system((python + " -c 'import lammps' > /dev/null 2>&1").c_str()) != 0) {
    rotlie::test::skip(python + " has no lammps module (Debian: python3-lammps)");
    return;
  }
  scratch d("python_module");
  const std::string input = water_head + sier4_water_run(d);
  auto text = [&] { return file_text(d.dir / "final.dump"); };
  BOOST_REQUIRE_MESSAGE(d.run("in.launcher", input) == 0, d.output);
  const std::string launcher = text();
  std::filesystem::remove(d.dir / "final.dump");
  const std::string loader_dir = std::filesystem::path(ROTLIE_LAMMPS_LOADER).parent_path().string();
  std::ofstream(d.dir / "in.module") << input;
  std::ofstream(d.dir / "drive.py") << "import sys\nsys.path.insert(0, '" << loader_dir << "')\n"
                                    << "from lammps import lammps\nimport rotlie_lammps\n"
                                    << "lmp = lammps(cmdargs=['-log', 'none', '-screen', 'none'])\n"
                                    << "rotlie_lammps.load_into(lmp)\nlmp.file('in.module')\nlmp.close()\n";
  const std::string cmd = "cd '" + d.dir.string() + "' && OMP_NUM_THREADS=1 " + python + " drive.py > drive.out 2>&1";
  BOOST_REQUIRE_MESSAGE(std::system(cmd.c_str()) == 0, "the Python program failed (drive.out in " << d.dir << ")");
  const std::string module = text();
  BOOST_TEST(launcher.size() > 3 * 216 * 6 * 17u);
  BOOST_TEST(launcher == module, "the lammps module with the loader differs from lmp_rotlie");
  BOOST_TEST_MESSAGE("lammps Python module + rotlie_lammps.load_into, 50 SIER4 steps: dump equal to lmp_rotlie's: " << (launcher == module));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(loader_errors_test)

using namespace rotlie_lammps_test;

namespace {

// How many lines of the output say `refused:`.
int lines_with_refused(const std::string& output) {
  std::istringstream in(output);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind("refused:", 0) == 0 ? 1 : 0;
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_module_that_fails_to_load_is_named_with_the_reason) {
  // lmp's python command says only "Python function evaluation failed": the loader says why first
  if (std::system("command -v lmp > /dev/null 2>&1") != 0) {
    rotlie::test::skip("no stock lmp");
    return;
  }
  scratch d("loader_reason");
  // the log holds what LAMMPS itself writes (its traceback goes to standard error only)
  const std::string input = std::string("log log.reason\npython rotlie_load input 1 SELF format p file ") + ROTLIE_LAMMPS_LOADER +
                            "\npython rotlie_load invoke\n";
  const int status = d.run("in.reason", input, 1, "", "ROTLIE_LAMMPS_PLUGIN=/nonexistent/rotlieplugin.so lmp");
  const std::string log = file_text(d.dir / "log.reason");
  BOOST_TEST(status != 0);
  BOOST_TEST(log.find("Python function evaluation failed") != std::string::npos, log);
  const auto reason = log.find("rotlie_lammps: OSError: cannot load rotlie's module /nonexistent/rotlieplugin.so");
  BOOST_TEST(reason != std::string::npos, log);
  BOOST_TEST(log.find("No such file", reason) != std::string::npos, log);
  BOOST_TEST_MESSAGE("a missing module under stock lmp, its log:\n" << log);
}

BOOST_AUTO_TEST_CASE(an_integer_is_refused_as_a_handle) {
  // load_into(12345) used to hand the number to C++ as an instance (a segmentation fault)
  scratch d("loader_integer");
  const std::string loader_dir = std::filesystem::path(ROTLIE_LAMMPS_LOADER).parent_path().string();
  std::ofstream(d.dir / "refuse.py") << "import sys\nsys.path.insert(0, '" << loader_dir << "')\nimport rotlie_lammps\n"
                                     << "for bad in (12345, None, 'lmp'):\n"
                                     << "    try:\n        rotlie_lammps.load_into(bad)\n"
                                     << "    except (TypeError, ValueError) as e:\n        print('refused:', type(e).__name__, e)\n";
  const std::string cmd = "cd '" + d.dir.string() + "' && " + ROTLIE_LAMMPS_PYTHON + " refuse.py > refuse.out 2>&1";
  const int status = std::system(cmd.c_str());
  const std::string output = file_text(d.dir / "refuse.out");
  BOOST_TEST(status == 0, output);
  BOOST_TEST(lines_with_refused(output) == 3, output);
  BOOST_TEST_MESSAGE("load_into(12345), (None), ('lmp'):\n" << output);
}

BOOST_AUTO_TEST_SUITE_END()
