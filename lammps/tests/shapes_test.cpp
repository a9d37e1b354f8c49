// SPDX-License-Identifier: GPL-2.0-or-later
// Body shapes the `rotor` keyword meets: symmetric tops under `rotor auto` run the exact rotor with
// one note, never a stop (LAMMPS's clumps example among them); `rotor auto` chooses from the shipped
// maps within seconds, the same on 1 and 2 ranks; a shape added during a run (fix deposit) runs the
// exact rotor with one note, under `rotor exact` and `rotor auto`.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "lmp_rotlie_runner.hpp"

using namespace rotlie_lammps_test;

namespace {

// A molecule template of 6 unit masses on the axes, at ±a, ±b, ±c: principal moments
// 2(b² + c²), 2(a² + c²), 2(a² + b²), so any body shape (I1, I2, I3) is a choice of a, b, c.
std::string axes_molecule(double I1, double I2, double I3) {
  const double a = std::sqrt((I2 + I3 - I1) / 4), b = std::sqrt((I1 + I3 - I2) / 4), c = std::sqrt((I1 + I2 - I3) / 4);
  std::ostringstream m;
  m.precision(17);
  m << "# axes body\n\n6 atoms\n\nCoords\n\n1 " << a << " 0 0\n2 " << -a << " 0 0\n3 0 " << b << " 0\n4 0 " << -b << " 0\n5 0 0 " << c
    << "\n6 0 0 " << -c << "\n\nTypes\n\n1 1\n2 1\n3 1\n4 1\n5 1\n6 1\n";
  return m.str();
}

// A regular tetrahedron (a spherical top) and an equilateral triangle (a symmetric top), as LAMMPS
// computes their moments from coordinates rounded to 17 digits.
const std::string tetrahedron = "# tetrahedron\n\n4 atoms\n\nCoords\n\n1 0.5 0.5 0.5\n2 -0.5 -0.5 0.5\n3 -0.5 0.5 -0.5\n4 0.5 -0.5 -0.5\n\n"
                                "Types\n\n1 1\n2 1\n3 1\n4 1\n";
const std::string triangle = "# triangle\n\n3 atoms\n\nCoords\n\n1 0.6 0 0\n2 -0.3 0.51961524227066314 0\n3 -0.3 -0.51961524227066314 0\n\n"
                             "Types\n\n1 1\n2 1\n3 1\n";

// LJ atoms in molecules of the templates given (file name → text), one template per slab of a
// simple cubic lattice of 4 × 4 × 4 sites, moving at T = 1; `fix` (and what follows) ends the input.
std::string bodies_input(scratch& d, const std::vector<std::pair<std::string, std::string>>& templates, const std::string& fix) {
  std::ostringstream in;
  in << "units lj\natom_style bond\nboundary p p p\nlattice sc 0.03\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1.0\n"
        "pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\nneigh_modify exclude molecule/intra all\n";
  const double slab = 4.0 / static_cast<double>(templates.size());
  for (std::size_t k = 0; k < templates.size(); ++k) {
    std::ofstream(d.dir / templates[k].first) << templates[k].second;
    in << "molecule m" << k << " " << templates[k].first << "\nregion r" << k << " block 0 4 0 4 " << slab * k << " " << slab * (k + 1)
       << "\ncreate_atoms 0 region r" << k << " mol m" << k << " " << 4321 + k << "\n";
  }
  in << "velocity all create 1.0 4928459\n" << fix;
  return in.str();
}

// The lines of the output that contain `what`.
std::vector<std::string> lines_with(const std::string& output, const std::string& what) {
  std::vector<std::string> out;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.find(what) != std::string::npos) out.push_back(line);
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(symmetric_tops_test)

BOOST_AUTO_TEST_CASE(symmetric_tops_run_the_exact_rotor_with_one_note) {
  scratch d("symmetric");
  const auto input = bodies_input(d, {{"tetra.mol", tetrahedron}, {"tri.mol", triangle}, {"asym.mol", axes_molecule(0.5, 0.7, 1.0)}},
                                  "fix r all rigid/sier2/small molecule rotor auto\ntimestep 0.002\nthermo 50\nrun 100\n");
  const int status = d.run("in.symmetric", input);
  BOOST_TEST(status == 0, d.output);
  const auto notes = lines_with(d.output, "the exact rotor runs");
  BOOST_TEST(notes.size() == 1u, d.output);
  if (!notes.empty()) {
    BOOST_TEST(notes.front().find("2 of 3 body shapes") != std::string::npos, notes.front());
    BOOST_TEST(notes.front().find("symmetric top") != std::string::npos, notes.front());
  }
  BOOST_TEST(lines_with(d.output, "ERROR").empty(), d.output);
  BOOST_TEST_MESSAGE("tetrahedra, triangles and an asymmetric body, rotor auto: " << (notes.empty() ? "(no note)" : notes.front()));
}

BOOST_AUTO_TEST_CASE(lammps_clumps_example_runs_with_rotor_auto) {
  // LAMMPS's rigid example (9 clumps of 9 atoms, custom bodies), its fix swapped (package lammps-examples)
  const std::filesystem::path example = "/usr/share/lammps/examples/rigid";
  if (!std::filesystem::exists(example / "in.rigid.atomvar") || !std::filesystem::exists(example / "data.rigid")) {
    rotlie::test::skip("no LAMMPS examples (Debian: lammps-examples)");
    return;
  }
  scratch d("clumps");
  std::filesystem::copy_file(example / "data.rigid", d.dir / "data.rigid");
  std::string input = file_text(example / "in.rigid.atomvar");
  const std::string fix = "fix 1 all rigid custom v_bodies";
  BOOST_REQUIRE(input.find(fix) != std::string::npos);
  input.replace(input.find(fix), fix.size(), "fix 1 all rigid/sier2/small custom v_bodies rotor auto");
  input.replace(input.rfind("run"), std::string::npos, "run 200\n");
  const auto start = std::chrono::steady_clock::now();
  const int status = d.run("in.clumps", input);
  const double seconds = seconds_since(start);
  BOOST_TEST(status == 0, d.output);
  BOOST_TEST(lines_with(d.output, "ERROR").empty(), d.output);
  BOOST_TEST(lines_with(d.output, "the exact rotor runs").size() <= 1u, d.output);
  BOOST_TEST(seconds < 60, seconds << " s");
  BOOST_TEST_MESSAGE("LAMMPS's clumps (in.rigid.atomvar), rotor auto, 200 steps: " << seconds << " s");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(shipped_maps_test)

BOOST_AUTO_TEST_CASE(rotor_auto_chooses_from_the_maps_in_seconds_on_1_and_2_ranks) {
  // (0.1835, 0.9875, 1) lies where the R map beats the reference (R:CBA:2 at the nearest grid body,
  // 5.4 × at equal cost); the other two where no family does (the reference at its permutation)
  scratch d("maps");
  const auto input = bodies_input(d,
                                  {{"r.mol", axes_molecule(0.367, 1.975, 2.0)},
                                   {"a.mol", axes_molecule(0.5, 0.7, 1.0)},
                                   {"b.mol", axes_molecule(0.6, 1.2, 1.5)}},
                                  "fix r all rigid/sier2/small molecule rotor auto\ntimestep 0.002\nthermo 50\nrun 50\n");
  std::vector<std::string> rotors[2];
  for (const int ranks : {1, 2}) {
    if (ranks > 1 && !have_mpirun()) continue;
    const auto start = std::chrono::steady_clock::now();
    const int status = d.run("in.maps", input, ranks);
    const double seconds = seconds_since(start);
    BOOST_TEST(status == 0, d.output);
    BOOST_TEST(lines_with(d.output, "from the shipped maps").size() == 1u, d.output);
    BOOST_TEST(seconds < 20, ranks << " rank(s): " << seconds << " s");
    // the rotor of each shape (the shapes' order and first bodies follow the ranks' bodies)
    for (const auto& line : lines_with(d.output, "body shape (")) rotors[ranks - 1].push_back(line.substr(line.rfind("rotor ")));
    std::sort(rotors[ranks - 1].begin(), rotors[ranks - 1].end());
    BOOST_TEST_MESSAGE(ranks << " rank(s), 3 shapes, rotor auto, 50 steps: " << seconds << " s");
    for (const auto& line : lines_with(d.output, "body shape (")) BOOST_TEST_MESSAGE(line);
  }
  BOOST_REQUIRE(rotors[0].size() == 3u);
  // sorted: R:CBA:n before the two RS4-S5-McLachlan:PERM
  BOOST_TEST(rotors[0][0].rfind("rotor R:CBA:", 0) == 0, rotors[0][0]);
  BOOST_TEST(rotors[0][1].rfind("rotor RS4-S5-McLachlan:", 0) == 0, rotors[0][1]);
  BOOST_TEST(rotors[0][2].rfind("rotor RS4-S5-McLachlan:", 0) == 0, rotors[0][2]);
  if (have_mpirun()) BOOST_TEST(rotors[0] == rotors[1], "1 and 2 ranks chose different rotors");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(new_shapes_test)

BOOST_AUTO_TEST_CASE(a_shape_deposited_during_a_run_runs_the_exact_rotor) {
  // bodies of one shape, then fix deposit adds bodies of another (its template: fix rigid/small's mol)
  for (const std::string rotor : {"exact", "auto"}) {
    scratch d("deposit_" + rotor);
    std::ofstream(d.dir / "new.mol") << axes_molecule(0.45, 0.8, 1.1);
    const std::string fix = "molecule fresh new.mol\nfix r all rigid/sier2/small molecule mol fresh rotor " + rotor +
                            "\nfix dep all deposit 4 0 20 12345 region box near 1.2 attempt 50 mol fresh rigid r units box\n"
                            "timestep 0.002\nthermo 50\nrun 200\n";
    const int status = d.run("in.deposit", bodies_input(d, {{"old.mol", axes_molecule(0.5, 0.7, 1.0)}}, fix));
    BOOST_TEST(status == 0, "rotor " << rotor << ":\n" << d.output);
    const auto notes = lines_with(d.output, "appeared during the run");
    BOOST_TEST(notes.size() == 1u, "rotor " << rotor << ":\n" << d.output);
    BOOST_TEST(lines_with(d.output, "ERROR").empty(), d.output);
    BOOST_TEST_MESSAGE("rotor " << rotor << ", fix deposit of a new shape: " << (notes.empty() ? "(no note)" : notes.front()));
  }
}

BOOST_AUTO_TEST_SUITE_END()
