// vZS section V.C says SIER4's h⁴ regime in liquid water is "frustrated by round-off". Here, on
// the 64-molecule system of liquid_water_dynamics_test (6 Å switched cutoff, 100 fs runs), the
// SIER4 energy fluctuation keeps its h⁴ slope down to h/f = 1/32 fs in double, and long double
// gives the same ratios (to 1 %): round-off does not frustrate it in this implementation.
// (`slow`: the long-double runs take about 20 s.)
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/water_setup.hpp"
#include "md_splittings.hpp"

BOOST_AUTO_TEST_SUITE(liquid_water_roundoff_test)

using namespace rotlie::models;

namespace {

template <class T>
liquid_water<T> small_water(T L) {
  liquid_water_options<T> o;
  o.box = L;
  o.cutoff = 6;
  o.switch_width = T(1.5);
  return liquid_water<T>(tip3p<T>(), o);
}

template <class T>
rigid_bodies_state<T> converted(const rigid_bodies_state<double>& s) {
  rigid_bodies_state<T> r;
  for (const auto& b : s.bodies) {
    rigid_body_state<T> c;
    for (int d = 0; d < 3; ++d) c.q[d] = b.q[d], c.p[d] = b.p[d], c.rot.G[d] = b.rot.G[d];
    for (std::size_t e = 0; e < 9; ++e) c.rot.Q.a[e] = b.rot.Q.a[e];
    r.bodies.push_back(c);
  }
  return r;
}

template <class T>
double fluctuation_ratio(const rigid_bodies_state<double>& start, double L, double h, double T_fs) {
  const auto w = small_water<T>(T(L));
  double out = 0;
  with_md_integrator(rotlie::test::splitting("SIER4"), nullptr, tip3p<T>().mass, tip3p<T>().moments, w, [&](const auto& m) {
    auto s = converted<T>(start);
    const auto& sys = m.system();
    const long n = std::lround(T_fs / h);
    const T e0 = sys.energy(s), v0 = sys.potential_energy(s);
    T es = 0, ess = 0, vs = 0, vss = 0;
    for (long k = 0; k < n; ++k) {
      m.step(s, T(h));
      const T V = sys.potential_energy(s), E = V + sys.kinetic_energy(s);
      es += E - e0, ess += (E - e0) * (E - e0), vs += V - v0, vss += (V - v0) * (V - v0);
    }
    const T N = static_cast<T>(n);
    out = static_cast<double>(std::sqrt(ess / N - es * es / (N * N)) / std::sqrt(vss / N - vs * vs / (N * N)));
    return 0;
  });
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(sier4_keeps_its_h4_slope_in_double_down_to_a_thirty_second_fs) {
  const double L = cubic_box_side<double>(64, tip3p<double>().mass, 0.9973);
  auto s = lattice_water<double>(tip3p<double>(), 64, L, 297, 4);
  const auto w = small_water<double>(L);
  with_md_integrator(rotlie::test::splitting("MRDL"), nullptr, tip3p<double>().mass, tip3p<double>().moments, w, [&](const auto& m) {
    equilibrate(m, s, 0.25, 400, 297.0, 10.0, [](long, double, double) {});
    equilibrate(m, s, 1.0, 1000, 297.0, 100.0, [](long, double, double) {});
    return 0;
  });
  s.forces_current = false;
  double previous = 0;
  for (double h : {1.0, 0.5, 0.25, 0.125}) {
    const double d = fluctuation_ratio<double>(s, L, h, 100), ld = fluctuation_ratio<long double>(s, L, h, 100);
    BOOST_TEST_MESSAGE("SIER4 h/f = " << h / 4 << " fs: ΔE/ΔV " << d << " (double), " << ld << " (long double)");
    BOOST_TEST(std::abs(d - ld) < 0.01 * ld);
    if (previous > 0) {
      const double local_slope = std::log2(previous / d);
      BOOST_TEST(std::abs(local_slope - 4) < 0.2, "local slope " << local_slope << " at h = " << h);
    }
    previous = d;
  }
}

BOOST_AUTO_TEST_SUITE_END()  // liquid_water_roundoff_test
