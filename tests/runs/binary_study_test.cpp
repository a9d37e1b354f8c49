// The binary scene's observables (runs/binary_study.hpp) against closed forms: at order 0 the mutual
// orbit's period is Kepler's; a small secondary about a spherical primary librates with the linear
// theory's period 2π / (n √(3(B − A)/C)); a tangential Δv changes the period as the vis-viva law says;
// a polyhedron of an ellipsoid moves as the ellipsoid does, to the mesh's error; the report's Didymos
// study: the cheapest splitting at an error, the sweep's steps dividing its span, DART against vis-viva.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

#include "rotlie/runs/didymos_study.hpp"

BOOST_AUTO_TEST_SUITE(binary_study_test)

using namespace rotlie;

namespace {

constexpr double pi = 3.141592653589793;

runs::binary_setup setup_of(runs::binary_request r) { return runs::binary_setup_of(r); }

runs::binary_request request(const std::string& primary, const std::string& secondary, const std::string& order, const std::string& integrator,
                             const std::string& h, const std::string& T) {
  runs::binary_request r;
  r.primary = primary, r.secondary = secondary, r.density = "2000", r.order = order, r.integrator = integrator, r.h = h, r.T = T;
  r.separation = "1.2", r.primary_period = "3";
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(at_order_zero_the_mutual_orbit_has_keplers_period) {
  const auto s = setup_of(request("ellipsoid:0.4,0.38,0.35", "ellipsoid:0.1,0.08,0.06", "0", "KEPLER4", "600", "432000"));
  const auto sys = s.system_model();
  const double kepler_h = 2 * pi * std::sqrt(1.2 * 1.2 * 1.2 / (s.G * sys.total_mass())) / 3600;
  const auto ob = runs::observe_binary(s, 1);
  BOOST_TEST_MESSAGE("order 0: " << ob.orbit_period_h << " h against Kepler's " << kepler_h << " h");
  BOOST_TEST(std::abs(ob.orbit_period_h / kepler_h - 1) < 1e-9);
  BOOST_TEST(ob.separation_max_km - ob.separation_min_km < 1e-9);
}

BOOST_AUTO_TEST_CASE(a_tangential_push_changes_the_period_as_vis_viva_says) {
  const auto s = setup_of(request("ellipsoid:0.4,0.38,0.35", "ellipsoid:0.1,0.08,0.06", "0", "KEPLER4", "600", "432000"));
  const double GM = s.G * s.system_model().total_mass(), dv = 2.5e-6;
  const double v = std::sqrt(models::dot(s.start.v, s.start.v)) - dv;
  const double a = 1 / (2 / 1.2 - v * v / GM);
  const double expected_h = 2 * pi * std::sqrt(a * a * a / GM) / 3600;
  const auto ob = runs::observe_binary(runs::with_impulse(s, dv), 1);
  BOOST_TEST_MESSAGE("after a push of 2.5 mm/s: " << ob.orbit_period_h << " h against " << expected_h << " h");
  // the period read from the mean angular rate over whole orbits of an ellipse: to about 1e-6
  BOOST_TEST(std::abs(ob.orbit_period_h / expected_h - 1) < 1e-5);
}

// A secondary 10⁻⁶ of the primary's mass about a sphere, turned 0.02 rad off the line of centres: a small
// libration at ω = n √(3(B − A)/C) (the pendulum of the spin–orbit problem at e = 0).
BOOST_AUTO_TEST_CASE(a_small_secondary_librates_at_the_linear_theorys_period) {
  auto r = request("ellipsoid:0.4,0.4,0.4", "ellipsoid:0.004,0.003,0.0025", "2", "KEPLER4", "60", "864000");
  r.mass = "5e11,5e5", r.density = "";
  const auto aligned = setup_of(r);
  const auto sys = aligned.system_model();
  const double n = aligned.start.v[1] / 1.2;
  const auto I = sys.moments(1);
  const double expected_h = 2 * pi / (n * std::sqrt(3 * (I[1] - I[0]) / I[2])) / 3600;
  auto s = aligned;
  s.start.body[1].Q = models::rotation<double>({0, 0, 1}, 0.02);
  const auto ob = runs::observe_binary(s, 1);
  BOOST_TEST_MESSAGE("libration " << ob.libration_amplitude_deg << "° with period " << ob.libration_period_h << " h against " << expected_h << " h");
  BOOST_TEST(std::abs(ob.libration_amplitude_deg - 0.02 * 180 / pi) < 1e-3);
  BOOST_TEST(std::abs(ob.libration_period_h / expected_h - 1) < 2e-3);
}

// The same pair with the primary given as a shape model of its ellipsoid (an octahedron subdivided five
// times, 8,192 facets): the orbit and the attitudes after a day agree to the mesh's error in the
// integrals (about 1e-3 relative).
BOOST_AUTO_TEST_CASE(a_polyhedron_of_an_ellipsoid_moves_as_the_ellipsoid) {
  const auto path = std::filesystem::temp_directory_path() / ("rotlie-ellipsoid-" + std::to_string(::getpid()) + ".obj");
  {
    std::vector<models::vec3<double>> v{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<std::array<int, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int level = 0; level < 5; ++level) {
      std::map<std::pair<int, int>, int> middle;
      const auto mid = [&](int i, int j) {
        const auto key = std::minmax(i, j);
        if (const auto found = middle.find(key); found != middle.end()) return found->second;
        const auto &x = v[static_cast<std::size_t>(i)], &y = v[static_cast<std::size_t>(j)];
        models::vec3<double> m{x[0] + y[0], x[1] + y[1], x[2] + y[2]};
        const double l = std::sqrt(models::dot(m, m));
        v.push_back({m[0] / l, m[1] / l, m[2] / l});
        return middle[key] = static_cast<int>(v.size()) - 1;
      };
      std::vector<std::array<int, 3>> finer;
      for (const auto& t : f) {
        const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        finer.push_back({t[0], ab, ca}), finer.push_back({ab, t[1], bc}), finer.push_back({ca, bc, t[2]}), finer.push_back({ab, bc, ca});
      }
      f = finer;
    }
    std::ofstream out(path);
    out.precision(17);
    out << "# an ellipsoid 0.4 x 0.38 x 0.35 km\n";
    for (const auto& p : v) out << "v " << 0.4 * p[0] << " " << 0.38 * p[1] << " " << 0.35 * p[2] << "\n";
    for (const auto& t : f) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  }
  auto as_mesh = request("polyhedron:" + path.string(), "ellipsoid:0.1,0.08,0.06", "4", "SIER4", "60", "86400");
  auto as_ellipsoid = request("ellipsoid:0.4,0.38,0.35", "ellipsoid:0.1,0.08,0.06", "4", "SIER4", "60", "86400");
  as_mesh.mass = as_ellipsoid.mass = "5e11,5e9", as_mesh.density = as_ellipsoid.density = "";
  const auto mesh = runs::binary_run(setup_of(as_mesh)), ellipsoid = runs::binary_run(setup_of(as_ellipsoid));
  std::filesystem::remove(path);
  const auto I_mesh = mesh.setup.system_model().moments(0), I_ell = ellipsoid.setup.system_model().moments(0);
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(I_mesh[k] / I_ell[k] - 1) < 5e-3);
  const double d = runs::binary_state_error(mesh.end.x, ellipsoid.end.x);
  BOOST_TEST_MESSAGE("after a day: the mesh's pair is " << d << " from the ellipsoid's");
  BOOST_TEST(d < 1e-2);
}

// Every splitting (and the LGVI) keeps the total angular momentum within 1e-13 relative over 10³ mutual
// orbits of the Didymos system (order 2, h = 480 s: 88,000 steps), sampled 10⁴ times along the run.
BOOST_AUTO_TEST_CASE(every_splitting_keeps_the_angular_momentum_over_a_thousand_orbits) {
  for (const char* name : {"SIER2", "SIER4", "SIER6", "KEPLER2", "KEPLER4", "KEPLER6", "SIER4/ABCBA2:ABC", "LGVI"}) {
    runs::binary_request r;
    r.system = "didymos", r.integrator = name, r.h = "480", r.T = "42240000";
    const auto result = runs::binary_run(runs::binary_setup_of(r));
    BOOST_TEST_MESSAGE(name << ": largest relative change of L over 1000 orbits " << result.check.max_rel_angular_momentum_error << ", of E "
                            << result.check.max_rel_energy_error);
    BOOST_TEST(result.check.max_rel_angular_momentum_error < 1e-13, name);
    BOOST_TEST(!result.check.unstable, name);
  }
}

// The goals' ratios read off a sweep: among the stable TV splittings of the anchor's order that reach its
// error, the cheapest; Odeint, RK4 and the LGVI are not candidates, however cheap.
BOOST_AUTO_TEST_CASE(the_cheapest_splitting_at_an_anchors_error) {
  runs::binary_cost_result sweep;
  const auto row = [](const std::string& name, int order, double h, double cpu, double error, bool unstable = false) {
    runs::binary_cost_row r{name, order, h};
    r.cpu_s = cpu, r.error = error, r.unstable = unstable;
    return r;
  };
  sweep.rows = {row("LGVI", 2, 30, 4.0, 1e-6),     row("RK4", 2, 480, 0.1, 1e-7),      row("odeint-rkf78:1e-13", 2, 480, 0.2, 1e-12),
                row("SIER2", 2, 120, 1.0, 1e-6),   row("KEPLER2", 2, 480, 0.5, 2e-6),  row("KEPLER2", 2, 240, 0.8, 5e-7),
                row("SIER4", 2, 480, 0.3, 1e-7, true), row("KEPLER4", 4, 480, 0.05, 1e-9), row("KEPLER6", 2, 480, 2.0, 1e-12)};
  const auto lgvi = runs::cheapest_splitting_at(sweep, 2, "LGVI", 30);
  BOOST_REQUIRE(lgvi.has_value());
  BOOST_REQUIRE(lgvi->found);
  // KEPLER2 at 480 s misses the error, SIER4 is unstable, KEPLER4 is of order 4: KEPLER2 at 240 s, 5 times cheaper
  BOOST_TEST(lgvi->best.integrator == "KEPLER2");
  BOOST_TEST(lgvi->best.h == 240);
  BOOST_TEST(lgvi->less_cpu);
  BOOST_TEST(lgvi->cpu_ratio == 5.0, boost::test_tools::tolerance(1e-15));
  // only KEPLER6 reaches RKF78's error, at ten times its CPU
  const auto rkf = runs::cheapest_splitting_at(sweep, 2, "odeint-rkf78:1e-13", 480);
  BOOST_REQUIRE(rkf.has_value());
  BOOST_TEST(rkf->best.integrator == "KEPLER6");
  BOOST_TEST(!rkf->less_cpu);
  BOOST_TEST(rkf->cpu_ratio == 10.0, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(!runs::cheapest_splitting_at(sweep, 2, "LGVI", 60).has_value());  // no such anchor run
  sweep.rows.pop_back();
  BOOST_TEST(!runs::cheapest_splitting_at(sweep, 2, "odeint-rkf78:1e-13", 480)->found);
}

// Every step of the report's sweep, and the reference's two, divide its span: each run ends on T exactly.
BOOST_AUTO_TEST_CASE(the_didymos_sweep_steps_divide_its_span) {
  for (const bool quick : {true, false})
    for (const double orbits : {2.0, 10.0, 1000.0}) {
      const auto plan = runs::didymos_cost_plan(orbits, quick);
      BOOST_TEST(plan.T == orbits * 42240);
      auto steps = plan.steps;
      steps.insert(steps.end(), {plan.adaptive_h, plan.reference_h, plan.reference_h / 2});
      for (const double h : steps) BOOST_TEST(std::fmod(plan.T, h) == 0, "h = " << h << " s, T = " << plan.T << " s");
    }
  BOOST_TEST(runs::didymos_span_s(2) == 172800);
  BOOST_TEST(runs::didymos_span_s(1.0 / 86400 * 89) == 60);  // 89 s rounds to a whole minute
}

// DART's Δv is β m U / M₂, and the period it leaves follows the vis-viva law about the mass the circular
// start balances (GM = v² r). The pair to degree 4 is not two point masses: the mean period read over
// 2 days departs from vis-viva's by 2-4 % (about 2 % over 12 days; the point-mass law itself is checked
// to 1e-5 above), while a wrong sign, unit or factor in Δv would be far outside 5 %.
BOOST_AUTO_TEST_CASE(darts_period_change_follows_the_vis_viva_law) {
  const runs::dart_impact dart{579.4, 6.1449, 3.61};
  const double T = runs::didymos_span_s(2);
  const auto d = runs::dart_period_change(dart, T);
  const auto start = runs::didymos_setup(4, "KEPLER4", 60, T, false).start;
  BOOST_TEST(d.dv_km_s == 3.61 * 579.4 * 6.1449 / d.secondary_mass_kg, boost::test_tools::tolerance(1e-15));
  const double r = std::sqrt(models::dot(start.r, start.r)), v = std::sqrt(models::dot(start.v, start.v)), GM = v * v * r;
  BOOST_REQUIRE(d.rows.size() == 3u);
  for (const auto& row : d.rows) {
    const double w = v - row.dv_km_s, a = 1 / (2 / r - w * w / GM);
    const double expected_min = (std::pow(a / r, 1.5) - 1) * d.period_before_h * 60;
    BOOST_TEST_MESSAGE("Δv " << row.dv_km_s * 1e6 << " mm/s: " << row.change_min << " min against vis-viva's " << expected_min << " min");
    BOOST_TEST(std::abs(row.change_min / expected_min - 1) < 0.05);
  }
}

// The β sweep (issue 45): along the track it is dart_period_change's push (the same period change at the
// same Δv, another code path), falls with β, keeps the secondary's spin planar (G on its axis to
// round-off); turned out of the plane it is not planar; the β for a target change lies between its neighbours.
BOOST_AUTO_TEST_CASE(darts_beta_sweep_is_the_push_at_each_beta) {
  const runs::dart_impact dart{579.4, 6.1449, 3.61};
  const double T = runs::didymos_span_s(2);
  const auto sweep = runs::dart_beta_sweep(dart, {2.0, 3.61, 5.0}, 3.61, 3, -30, T);
  BOOST_REQUIRE(sweep.rows.size() == 4u);
  const auto single = runs::dart_period_change(dart, T);
  BOOST_TEST(sweep.rows[1].dv_km_s == single.dv_km_s, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(sweep.rows[1].change_min == single.rows[0].change_min, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(sweep.rows[0].change_min > sweep.rows[1].change_min);
  BOOST_TEST(sweep.rows[1].change_min > sweep.rows[2].change_min);
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(sweep.rows[k].npa_angle_max_deg < 1e-9);
    BOOST_TEST(!sweep.rows[k].tumbling);
  }
  BOOST_TEST(sweep.rows[3].tilt_deg == 3.0);
  BOOST_TEST(sweep.rows[3].npa_angle_max_deg > 1e-6);
  const auto& lo = sweep.rows[0];
  const auto& hi = sweep.rows[1];
  BOOST_TEST((sweep.beta_for_target > lo.beta && sweep.beta_for_target < hi.beta));
  const double interpolated = lo.change_min + (sweep.beta_for_target - lo.beta) / (hi.beta - lo.beta) * (hi.change_min - lo.change_min);
  BOOST_TEST(interpolated == -30.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()  // binary_study_test
