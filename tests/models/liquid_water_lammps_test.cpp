// rotlie against LAMMPS (`lmp`, skipped where it is missing) on 512 TIP3P molecules in the same
// box with the same site pair style, lj/cut/coul/dsf: the potential energy and every site force
// of one configuration agree to 1e-9 relative; 100 NO_SQUISH steps of fix rigid/nve/small
// against rotlie's MRDL, which runs the same planar-rotation sequence (Strang-TV with ABCBA2:ABC
// in rotlie's increasing-moment axes; see the comment in the second test), and against
// MRDL-reversed (ABCBA2:CBA), a different map.
#include <boost/test/unit_test.hpp>

#include "skip.hpp"
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <unistd.h>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/lammps_water_io.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(liquid_water_lammps_test)

using namespace rotlie::models;
namespace fs = std::filesystem;

namespace {

bool have_lammps() { return std::system("command -v lmp > /dev/null 2>&1") == 0; }

struct lammps_dir {
  fs::path dir = fs::temp_directory_path() / ("rotlie_lammps_" + std::to_string(::getpid()));
  lammps_dir() { fs::create_directories(dir); }
  ~lammps_dir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  /// Runs lmp on `input` in the folder; true on success.
  bool run(const std::string& input) const {
    std::ofstream(dir / "in.water") << input;
    const std::string cmd = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 lmp -log none -screen none -in in.water > lmp.out 2>&1";
    return std::system(cmd.c_str()) == 0;
  }
  double number_after(const std::string& key) const {
    std::ifstream in(dir / "result.txt");
    std::string k;
    double v = NAN;
    while (in >> k >> v)
      if (k == key) return v;
    return NAN;
  }
};

liquid_water<double> dsf_water(double L) {
  liquid_water_options<double> o;
  o.box = L;
  o.interaction = water_interaction::lammps_dsf;
  return liquid_water<double>(tip3p<double>(), o);
}

/// A liquid-like start: the lattice, thermal momenta, and 300 steps at 0.5 fs under a Berendsen
/// thermostat so that molecules sit at liquid distances (the switched potential; cheap).
const rigid_bodies_state<double>& small_liquid(long n, double L) {
  static rigid_bodies_state<double> s;  // built once for both tests
  if (!s.bodies.empty()) return s;
  s = lattice_water<double>(tip3p<double>(), n, L, 297, 21);
  liquid_water_options<double> o;
  o.box = L;
  const liquid_water<double> w(tip3p<double>(), o);
  with_md_integrator(rotlie::test::splitting("MRDL"), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    equilibrate(m, s, 0.5, 300, 297.0, 20.0, [](long, double, double) {});
    return 0;
  });
  return s;
}

const std::string lammps_head = "units real\natom_style full\nboundary p p p\nread_data water.data\n";

}  // namespace

BOOST_AUTO_TEST_CASE(energy_and_site_forces_agree_with_lammps) {
  if (!have_lammps()) {
    rotlie::test::skip("lmp (LAMMPS) is not installed");
    return;
  }
  const long n = 512;
  const double L = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  const auto s = small_liquid(n, L);
  const auto w = dsf_water(L);
  std::vector<vec3<double>> f;
  const double V = w.evaluate_sites(s.bodies, f);
  lammps_dir d;
  write_lammps_water_data(d.dir / "water.data", w, s.bodies);
  BOOST_REQUIRE(d.run(lammps_head + lammps_water_pair_lines(w) +
                      "dump f all custom 1 forces.dump id fx fy fz\ndump_modify f format float %.17g sort id\n"
                      "thermo_style custom step pe\nrun 0\nprint \"pe $(pe:%.17g)\" file result.txt\n"));
  const double V_lammps = d.number_after("pe");
  BOOST_TEST_MESSAGE("V: rotlie " << std::setprecision(17) << V << ", LAMMPS " << V_lammps << " kcal/mol");
  BOOST_TEST(std::abs(V - V_lammps) < 1e-9 * std::abs(V_lammps));
  const auto rows = read_lammps_dump(d.dir / "forces.dump");
  BOOST_REQUIRE(rows.size() == 3 * static_cast<std::size_t>(n));
  double worst = 0, scale = 0;
  for (const auto& [id, F] : rows)
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(F[k] - f[static_cast<std::size_t>(id - 1)][k]));
      scale = std::max(scale, std::abs(F[k]));
    }
  BOOST_TEST_MESSAGE("site forces: largest difference " << worst << " kcal/mol/Å, largest force " << scale);
  BOOST_TEST(worst < 1e-9 * scale);
}

BOOST_AUTO_TEST_CASE(a_hundred_steps_of_no_squish_agree_with_fix_rigid_nve_small) {
  if (!have_lammps()) {
    rotlie::test::skip("lmp (LAMMPS) is not installed");
    return;
  }
  const long n = 512;
  const double L = cubic_box_side<double>(n, tip3p<double>().mass, 0.9973);
  const auto s0 = small_liquid(n, L);
  const auto w = dsf_water(L);
  lammps_dir d;
  write_lammps_water_data(d.dir / "water.data", w, s0.bodies);
  BOOST_REQUIRE(d.run(lammps_head + lammps_water_pair_lines(w) +
                      "fix r all rigid/nve/small molecule\ntimestep 1.0\nthermo_style custom step pe\nrun 100\n"
                      "write_dump all custom final.dump id xu yu zu modify format float %.17g sort id\n"));
  const auto rows = read_lammps_dump(d.dir / "final.dump");
  BOOST_REQUIRE(rows.size() == 3 * static_cast<std::size_t>(n));
  // LAMMPS sorts the principal axes by decreasing moment and applies NO_SQUISH's planar rotations
  // 3, 2, 1, 2, 3 (full step on its axis 1): in rotlie's increasing order that is the smallest,
  // the intermediate, the largest (full), … — ABCBA2 with the identity permutation, MRDL's rotor.
  auto distance_after = [&](const std::string& integrator) {
    auto s = s0;
    s.forces_current = false;  // the cache holds the equilibration potential's forces
    with_md_integrator(rotlie::test::splitting(integrator), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
      for (int k = 0; k < 100; ++k) m.step(s, 1.0);
      return 0;
    });
    std::vector<vec3<double>> x;
    w.site_positions(s.bodies, x);
    double worst = 0;
    for (const auto& [id, r] : rows) {
      // LAMMPS's unwrapped coordinates start from the wrapped centres: compare modulo the box
      const vec3<double> dx = minimum_image(vec3<double>{r[0] - x[static_cast<std::size_t>(id - 1)][0], r[1] - x[static_cast<std::size_t>(id - 1)][1],
                                                         r[2] - x[static_cast<std::size_t>(id - 1)][2]},
                                            L);
      worst = std::max(worst, std::sqrt(dot(dx, dx)));
    }
    return worst;
  };
  const double mrdl = distance_after("MRDL"), reversed = distance_after("MRDL-reversed");
  BOOST_TEST_MESSAGE("after 100 steps of 1 fs, largest site distance to LAMMPS: MRDL (ABCBA2:ABC) " << mrdl
                                                                                                     << " Å, MRDL-reversed (ABCBA2:CBA) " << reversed << " Å");
  BOOST_TEST(mrdl < 1e-9, "MRDL is LAMMPS's map: round-off growth only (6e-15 Å after one step)");
  BOOST_TEST(reversed > 1e3 * mrdl, "MRDL-reversed is a different map (O(h³) per step)");
}

BOOST_AUTO_TEST_SUITE_END()  // liquid_water_lammps_test
