// NVE dynamics of liquid water (vZS Fig. 1 on a small system): the rms energy fluctuation over
// the rms potential fluctuation scales as h² for SIER2 and as h⁴ for SIER4 (fitted slopes), total
// momentum is conserved to round-off in the periodic box, and total angular momentum of an
// isolated cluster (no image within the cutoff) to round-off.
//
// The small system: 64 TIP3P molecules at 0.9973 g/cm³ (a 12.4 Å box) with the same smooth
// molecular cutoff scaled down to 6 Å (switch 4.5–6 Å), so that the run costs a second; the
// 512-molecule scene with the 11 Å cutoff is what `rotlie md --scene liquid-water` and the report run.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_observables.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(liquid_water_dynamics_test)

using namespace rotlie::models;

namespace {

liquid_water<double> small_water(double L, double cutoff) {
  liquid_water_options<double> o;
  o.box = L;
  o.cutoff = cutoff;
  o.switch_width = 1.5;
  return liquid_water<double>(tip3p<double>(), o);
}

const double small_box = cubic_box_side<double>(64, tip3p<double>().mass, 0.9973);

/// 64 molecules equilibrated for 1 ps at 297 K (Berendsen), built once.
const rigid_bodies_state<double>& small_liquid() {
  static rigid_bodies_state<double> s;
  if (!s.bodies.empty()) return s;
  s = lattice_water<double>(tip3p<double>(), 64, small_box, 297, 4);
  const auto w = small_water(small_box, 6);
  with_md_integrator(rotlie::test::splitting("MRDL"), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    equilibrate(m, s, 0.25, 400, 297.0, 10.0, [](long, double, double) {});
    equilibrate(m, s, 1.0, 1000, 297.0, 100.0, [](long, double, double) {});
    return 0;
  });
  s.forces_current = false;
  return s;
}

/// rms(E)/rms(V) over T fs of NVE from the small liquid, sampled every step.
double fluctuation_ratio(const std::string& integrator, double h, double T) {
  const auto w = small_water(small_box, 6);
  double ratio = 0;
  with_md_integrator(rotlie::test::splitting(integrator), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    auto s = small_liquid();
    const auto& sys = m.system();
    const long steps = std::lround(T / h);
    const double e0 = sys.energy(s), v0 = sys.potential_energy(s);
    double es = 0, ess = 0, vs = 0, vss = 0;
    for (long k = 0; k < steps; ++k) {
      m.step(s, h);
      const double V = sys.potential_energy(s), E = V + sys.kinetic_energy(s);
      es += E - e0;
      ess += (E - e0) * (E - e0);
      vs += V - v0;
      vss += (V - v0) * (V - v0);
    }
    const double n = static_cast<double>(steps);
    ratio = std::sqrt(ess / n - es * es / (n * n)) / std::sqrt(vss / n - vs * vs / (n * n));
    return 0;
  });
  return ratio;
}

/// Least-squares slope of log(y) against log(x).
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

BOOST_AUTO_TEST_CASE(sier2_energy_fluctuation_scales_as_h_squared) {
  // window h = 0.5 … 2 fs over 200 fs
  const std::vector<double> h{2.0, 1.0, 0.5};
  std::vector<double> r;
  for (double x : h) r.push_back(fluctuation_ratio("SIER2", x, 200));
  const double p = fitted_slope(h, r);
  BOOST_TEST_MESSAGE("SIER2 ΔE/ΔV: " << r[0] << ", " << r[1] << ", " << r[2] << " at h = 2, 1, 0.5 fs; slope " << p);
  BOOST_TEST(std::abs(p - 2) < 0.2);
}

BOOST_AUTO_TEST_CASE(sier4_energy_fluctuation_scales_as_h_to_the_fourth) {
  // window h = 1 … 4 fs (h/f = 0.25 … 1 fs) over 200 fs; at h = 8 fs the local slope is 4.5
  const std::vector<double> h{4.0, 2.0, 1.0};
  std::vector<double> r;
  for (double x : h) r.push_back(fluctuation_ratio("SIER4", x, 200));
  const double p = fitted_slope(h, r);
  BOOST_TEST_MESSAGE("SIER4 ΔE/ΔV: " << r[0] << ", " << r[1] << ", " << r[2] << " at h = 4, 2, 1 fs; slope " << p);
  BOOST_TEST(std::abs(p - 4) < 0.4);
}

BOOST_AUTO_TEST_CASE(total_momentum_is_conserved_to_round_off) {
  const auto w = small_water(small_box, 6);
  for (const char* name : {"SIER2", "SIER4", "MRDL", "SEJ4"})
    with_md_integrator(rotlie::test::splitting(name), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
      auto s = small_liquid();
      const vec3<double> P0 = total_momentum(s);
      double scale = 0;
      for (const auto& b : s.bodies) scale += std::sqrt(dot(b.p, b.p));
      for (int k = 0; k < 100; ++k) m.step(s, 2.0);
      const vec3<double> P = total_momentum(s);
      const double drift = std::sqrt((P[0] - P0[0]) * (P[0] - P0[0]) + (P[1] - P0[1]) * (P[1] - P0[1]) + (P[2] - P0[2]) * (P[2] - P0[2]));
      BOOST_TEST_MESSAGE(name << ": |ΔP| = " << drift << " against Σ|p| = " << scale);
      BOOST_TEST(drift < 1e-13 * scale);
      return 0;
    });
}

BOOST_AUTO_TEST_CASE(angular_momentum_of_an_isolated_cluster_is_conserved_to_round_off) {
  // 27 molecules from the small liquid, re-centred in a 60 Å box: no image within 11 Å
  const auto& liquid = small_liquid();
  rigid_bodies_state<double> s;
  for (int i = 0; i < 27; ++i) s.bodies.push_back(liquid.bodies[static_cast<std::size_t>(i)]);
  vec3<double> P{};
  for (const auto& b : s.bodies)
    for (int d = 0; d < 3; ++d) P[d] += b.p[d];
  for (auto& b : s.bodies)
    for (int d = 0; d < 3; ++d) {
      b.q[d] += 30 - small_box / 2;
      b.p[d] -= P[d] / 27;
    }
  const auto w = small_water(60, 11);
  for (const char* name : {"SIER2", "SIER4", "MRDL"})
    with_md_integrator(rotlie::test::splitting(name), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
      auto x = s;
      const vec3<double> L0 = total_angular_momentum(x);
      double scale = 0;
      for (const auto& b : x.bodies) scale += std::sqrt(dot(b.rot.G, b.rot.G)) + std::sqrt(dot(cross(b.q, b.p), cross(b.q, b.p)));
      for (int k = 0; k < 100; ++k) m.step(x, 2.0);
      const vec3<double> L = total_angular_momentum(x);
      const double drift = std::sqrt((L[0] - L0[0]) * (L[0] - L0[0]) + (L[1] - L0[1]) * (L[1] - L0[1]) + (L[2] - L0[2]) * (L[2] - L0[2]));
      BOOST_TEST_MESSAGE(name << ": |ΔL| = " << drift << " against Σ|L_i| = " << scale);
      BOOST_TEST(drift < 1e-12 * scale);
      return 0;
    });
}

BOOST_AUTO_TEST_CASE(the_pair_list_is_rebuilt_before_a_pair_is_missed) {
  // 400 steps of 2 fs: molecules move several skins; the running potential (list rebuilt when a
  // site moved more than skin/2) and a fresh one (list built now) must give the same energy
  const auto w = small_water(small_box, 6);
  with_md_integrator(rotlie::test::splitting("SIER2"), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    auto s = small_liquid();
    const long before = w.list_builds();
    for (int k = 0; k < 400; ++k) m.step(s, 2.0);
    const auto fresh = small_water(small_box, 6);
    std::vector<vec3<double>> f(s.bodies.size()), t(s.bodies.size()), f2(s.bodies.size()), t2(s.bodies.size());
    const double V = w.evaluate(s.bodies, f, t), V2 = fresh.evaluate(s.bodies, f2, t2);
    BOOST_TEST_MESSAGE("list builds in 400 steps: " << w.list_builds() - before << "; V " << V << " against a fresh list " << V2);
    BOOST_TEST(w.list_builds() - before >= 2);
    BOOST_TEST(std::abs(V - V2) < 1e-12 * std::abs(V2));
    double worst = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(f[i][k] - f2[i][k]));
    BOOST_TEST(worst < 1e-10);
    return 0;
  });
}

BOOST_AUTO_TEST_CASE(overlapping_molecules_are_refused) {
  auto s = small_liquid();
  s.bodies[5].q = s.bodies[3].q;
  s.bodies[5].q[0] += 0.7;
  const auto w = small_water(small_box, 6);
  std::vector<vec3<double>> x, o;
  w.site_positions(s.bodies, x);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) o.push_back(x[3 * i]);
  const auto c = closest_oxygens(o, small_box, 2.0);
  BOOST_TEST(c.i == 3);
  BOOST_TEST(c.j == 5);
  BOOST_TEST(c.distance < 2.0);
  w.site_positions(small_liquid().bodies, x);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) o[i] = x[3 * i];
  const auto ok = closest_oxygens(o, small_box, 2.0);
  BOOST_TEST(ok.i == -1);  // the liquid itself has no O–O closer than 2 Å
}

BOOST_AUTO_TEST_SUITE_END()  // liquid_water_dynamics_test
