// The binary observer's rotation diagnostics (runs/binary_observables.hpp) against closed forms: Euler
// angles built by hand read back; the dynamical inertia I_d = |G|²/(2E) and the SAM/LAM split at I_d = B;
// a torque-free body (order 0: point masses, no torques) in pure spin about C reads 0 and does not tumble;
// an axisymmetric one (A = B) with G at α off C keeps G on a cone of half-angle α; a triaxial one started
// in the A–C plane at α reaches asin(sin α √((1/A − 1/C)/(1/B − 1/C))) off C where its polhode crosses
// the B–C plane (SAM), or 90° (LAM); Didymos unperturbed does not tumble, pushed out of its plane it does,
// and a DART-size libration turns a small out-of-plane tilt into tumbling.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "rotlie/runs/binary_run.hpp"

BOOST_AUTO_TEST_SUITE(binary_tumbling_test)

using namespace rotlie;

namespace {

constexpr double pi = 3.141592653589793;
constexpr double degree = pi / 180;

models::mat3<double> turn(int axis, double angle) {
  models::vec3<double> u{0, 0, 0};
  u[static_cast<std::size_t>(axis)] = 1;
  return models::rotation<double>(u, angle);
}

// Two bodies 1.2 km apart at order 0 (no torques), the secondary's G set to |G| (sin α, 0, cos α).
runs::binary_setup free_pair(const std::string& secondary, double alpha) {
  runs::binary_request r;
  r.primary = "ellipsoid:0.4,0.38,0.35", r.secondary = secondary, r.density = "2000", r.order = "0";
  r.integrator = "SIER4", r.h = "60", r.T = "172800", r.separation = "1.2", r.primary_period = "3";
  auto s = runs::binary_setup_of(r);
  const auto I = s.system_model().moments(1);
  const double G = I[2] * 2 * pi / (6 * 3600);  // a 6 h spin about C
  s.start.body[1].G = {G * std::sin(alpha), 0, G * std::cos(alpha)};
  s.observe = true, s.error_estimate = false;
  return s;
}

runs::binary_observables observed(const runs::binary_setup& s) { return *runs::binary_run(s).observables; }

double hand_inertia(const models::vec3<double>& I, double alpha) {
  return 1 / (std::sin(alpha) * std::sin(alpha) / I[0] + std::cos(alpha) * std::cos(alpha) / I[2]);
}

runs::binary_setup didymos(const std::string& impulse, const std::string& T = "864000") {
  runs::binary_request r;
  r.system = "didymos", r.integrator = "SIER4", r.h = "60", r.T = T, r.impulse = impulse, r.observe = true, r.no_error_estimate = true;
  return runs::binary_setup_of(r);
}

}  // namespace

// An attitude R_x(φ) R_y(θ) R_z(ψ) in an inclined orbit frame reads back as (φ, θ, ψ), and the same with a
// half turn about any body axis (the axes carry no arrow).
BOOST_AUTO_TEST_CASE(euler_angles_built_by_hand_read_back) {
  models::binary_state<double> x;
  x.r = {0.9, 0.5, 0.3}, x.v = {-0.2, 0.7, 0.4};
  models::mat3<double> F;
  BOOST_TEST_REQUIRE(runs::orbit_frame(x, F));
  BOOST_TEST(std::abs(F(0, 0) * x.r[0] + F(1, 0) * x.r[1] + F(2, 0) * x.r[2] - models::norm(x.r)) < 1e-15);
  const double roll = 0.3, pitch = -0.2, yaw = 0.7;
  const auto R = turn(0, roll) * turn(1, pitch) * turn(2, yaw);
  for (int half = -1; half < 3; ++half) {
    x.body[1].Q = F * R * (half < 0 ? models::mat3<double>::identity() : turn(half, pi));
    const auto e = runs::orbit_euler_angles(x, 1);
    BOOST_TEST_MESSAGE("half turn about " << half << ": " << e[0] << ", " << e[1] << ", " << e[2]);
    BOOST_TEST(std::abs(e[0] - roll) < 1e-14);
    BOOST_TEST(std::abs(e[1] - pitch) < 1e-14);
    BOOST_TEST(std::abs(e[2] - yaw) < 1e-14);
  }
  // on a planar orbit yaw is the libration angle
  x.r = {0.6, 0.8, 0}, x.v = {-0.8, 0.6, 0};
  x.body[1].Q = turn(2, std::atan2(0.8, 0.6) + 2.9);
  const auto e = runs::orbit_euler_angles(x, 1);
  BOOST_TEST(std::abs(e[2] - runs::libration_angle(x)) < 1e-14);
  BOOST_TEST(std::abs(e[2] - (2.9 - pi)) < 1e-14);
  BOOST_TEST(e[0] == 0);
  BOOST_TEST(e[1] == 0);
}

// I_d = |G|²/(2E) by hand; SAM exactly when I_d ≥ B; the angle off C, and off the plane of two equal
// maximum moments.
BOOST_AUTO_TEST_CASE(dynamical_inertia_and_the_angle_off_c_by_hand) {
  const models::vec3<double> I{2, 3, 5};
  const models::vec3<double> G{0.3, -0.4, 1.2};
  const double E = (0.09 / 2 + 0.16 / 3 + 1.44 / 5) / 2;
  BOOST_TEST(std::abs(runs::dynamical_inertia(I, G) - (0.09 + 0.16 + 1.44) / (2 * E)) < 1e-15);
  BOOST_TEST(std::abs(runs::max_moment_angle(I, G) - std::atan2(0.5, 1.2)) < 1e-15);
  BOOST_TEST(std::abs(runs::dynamical_inertia(I, {0, 0, 7}) - 5) < 1e-15);
  BOOST_TEST(std::abs(runs::dynamical_inertia(I, {7, 0, 0}) - 2) < 1e-15);
  BOOST_TEST(runs::max_moment_angle(I, {0, 0, -7}) == 0);
  BOOST_TEST(std::abs(runs::max_moment_angle(I, {7, 0, 0}) - pi / 2) < 1e-15);
  // the body frame need not be sorted: C along x
  BOOST_TEST(std::abs(runs::max_moment_angle({5, 3, 2}, {1.2, -0.4, 0.3}) - std::atan2(0.5, 1.2)) < 1e-15);
  // a prolate body (B = C): the angle to the B–C plane
  BOOST_TEST(std::abs(runs::max_moment_angle({2, 5, 5}, {0.3, -0.4, 1.2}) - std::atan2(0.3, std::hypot(0.4, 1.2))) < 1e-15);
  BOOST_TEST(runs::max_moment_angle({4, 4, 4}, {0.3, -0.4, 1.2}) == 0);
}

BOOST_AUTO_TEST_CASE(a_free_body_spinning_about_c_does_not_tumble) {
  const auto o = observed(free_pair("ellipsoid:0.1,0.08,0.06", 0));
  for (const auto& rot : o.rotation) {
    BOOST_TEST_MESSAGE("angle " << rot.npa_angle_max_deg << "°, I_d/C " << rot.id_over_c);
    BOOST_TEST(rot.npa_angle_max_deg == 0);
    BOOST_TEST(std::abs(rot.id_over_c - 1) < 1e-15);
    BOOST_TEST(rot.short_axis_mode);
    BOOST_TEST(!rot.tumbling);
  }
  BOOST_TEST(o.tumbling_threshold_deg == runs::default_tumbling_threshold_deg);
}

// A = B: the body-frame G turns about C on a cone of half-angle α (Euler's axisymmetric top).
BOOST_AUTO_TEST_CASE(an_axisymmetric_free_body_keeps_g_on_its_cone) {
  const double alpha = 20 * degree;
  const auto s = free_pair("ellipsoid:0.1,0.1,0.06", alpha);
  const auto I = s.system_model().moments(1);
  BOOST_TEST_REQUIRE(I[0] == I[1]);
  const auto o = observed(s);
  const auto& rot = o.rotation[1];
  BOOST_TEST_MESSAGE("cone " << rot.npa_angle_max_deg << "° (end " << rot.npa_angle_end_deg << "°) against " << alpha / degree << "°; I_d/C "
                             << rot.id_over_c << " against " << hand_inertia(I, alpha) / I[2]);
  BOOST_TEST(std::abs(rot.npa_angle_max_deg - 20) < 1e-10);
  BOOST_TEST(std::abs(rot.npa_angle_end_deg - 20) < 1e-10);
  BOOST_TEST(std::abs(rot.id_over_c - hand_inertia(I, alpha) / I[2]) < 1e-12);
  BOOST_TEST(rot.short_axis_mode);
  BOOST_TEST(rot.tumbling);
  BOOST_TEST(!o.rotation[0].tumbling);
}

// A < B < C: started in the A–C plane at α, the polhode circles C (SAM, I_d > B) and is farthest from it
// where it crosses the B–C plane, or circles A (LAM, I_d < B) and crosses the A–B plane, 90° off C.
BOOST_AUTO_TEST_CASE(a_triaxial_free_body_sam_or_lam_as_the_closed_form_says) {
  for (const double alpha_deg : {15.0, 40.0, 75.0}) {
    const double alpha = alpha_deg * degree;
    const auto s = free_pair("ellipsoid:0.1,0.08,0.06", alpha);
    const auto I = s.system_model().moments(1);
    const double Id = hand_inertia(I, alpha);
    const bool sam = Id >= I[1];
    const double sin_max = std::sin(alpha) * std::sqrt((1 / I[0] - 1 / I[2]) / (1 / I[1] - 1 / I[2]));
    const double expected_deg = sam ? std::asin(sin_max) / degree : 90;
    // LAM: G_C passes through 0 at the rate |G_A G_B (1/B − 1/A)| (Euler's equation at G_C = 0, G_A and G_B
    // from |G| and E there), so the nearest sample misses 90° by up to that rate × h/2 over |G|
    const double G = models::norm(s.start.body[1].G), E = G * G / (2 * Id);
    const double GB2 = (2 * E - G * G / I[0]) / (1 / I[1] - 1 / I[0]), GA2 = G * G - GB2;
    const double miss_deg = sam ? 1e-3 : std::sqrt(GA2 * GB2) * (1 / I[0] - 1 / I[1]) * s.h / 2 / G / degree;
    const auto rot = observed(s).rotation[1];
    BOOST_TEST_MESSAGE("α = " << alpha_deg << "°: I_d/B " << Id / I[1] << " " << (rot.short_axis_mode ? "SAM" : "LAM") << ", farthest off C "
                              << rot.npa_angle_max_deg << "° against " << expected_deg << "° (within " << miss_deg << "°)");
    BOOST_TEST(rot.short_axis_mode == sam);
    BOOST_TEST(std::abs(rot.id_over_c - Id / I[2]) < 1e-12);
    // SAM: the samples (a minute apart) straddle a smooth maximum, the miss second order in the step
    BOOST_TEST(std::abs(rot.npa_angle_max_deg - expected_deg) < miss_deg);
    BOOST_TEST(rot.npa_angle_max_deg >= alpha_deg - 1e-10);
    BOOST_TEST(rot.tumbling);
  }
  // the three starts span both modes
  const auto I = free_pair("ellipsoid:0.1,0.08,0.06", 0).system_model().moments(1);
  BOOST_TEST(hand_inertia(I, 15 * degree) > I[1]);
  BOOST_TEST(hand_inertia(I, 75 * degree) < I[1]);
}

// Didymos unperturbed: a planar pair, G stays along each C (the libration's torque is along the pole);
// pushed by 5 mm/s out of the orbit plane the secondary's orbit tilts under it and the mutual torque
// drives G off C.
BOOST_AUTO_TEST_CASE(didymos_tumbles_only_when_pushed_out_of_its_plane) {
  const auto calm = observed(didymos(""));
  for (const auto& rot : calm.rotation) BOOST_TEST(!rot.tumbling);
  const auto& sec = calm.rotation[1];
  BOOST_TEST_MESSAGE("unperturbed: secondary " << sec.npa_angle_max_deg << "° off C, roll/pitch/yaw " << sec.euler_max_deg[0] << ", "
                                               << sec.euler_max_deg[1] << ", " << sec.euler_max_deg[2] << "°, libration " << calm.libration_amplitude_deg
                                               << "°");
  BOOST_TEST(sec.npa_angle_max_deg < 1e-9);
  BOOST_TEST(sec.euler_max_deg[0] < 1e-9);
  BOOST_TEST(sec.euler_max_deg[1] < 1e-9);
  // yaw is the libration: its largest size at least the half range
  BOOST_TEST(sec.euler_max_deg[2] >= calm.libration_amplitude_deg - 1e-12);
  const auto pushed = observed(didymos("secondary:0,0,5"));
  const auto& tilted = pushed.rotation[1];
  BOOST_TEST_MESSAGE("pushed 5 mm/s out of plane: secondary " << tilted.npa_angle_max_deg << "° off C, I_d/C " << tilted.id_over_c << ", roll/pitch "
                                                             << tilted.euler_max_deg[0] << ", " << tilted.euler_max_deg[1] << "°, i = "
                                                             << pushed.osculating.i_deg << "°");
  BOOST_TEST(tilted.tumbling);
  BOOST_TEST(tilted.short_axis_mode);
}

// A DART-size push against the orbital motion (2.6 mm/s) excites a libration of about 21°. Exactly in the
// plane the pair stays planar and G on C; with 0.01 mm/s out of the plane besides, roll and pitch grow from
// 0.004° to tens of degrees within 30 days (the planar libration is unstable out of the plane), and G
// leaves C by about 25°: tumbling, in the short-axis mode.
BOOST_AUTO_TEST_CASE(a_dart_size_libration_grows_a_small_tilt_into_tumbling) {
  const auto planar = observed(didymos("secondary:0,-2.6,0", "2592000"));
  BOOST_TEST(planar.libration_amplitude_deg > 20);
  BOOST_TEST(!planar.rotation[1].tumbling);
  BOOST_TEST(planar.rotation[1].npa_angle_max_deg < 1e-9);
  const auto seeded = observed(didymos("secondary:0,-2.6,0.01", "2592000"));
  const auto& rot = seeded.rotation[1];
  BOOST_TEST_MESSAGE("seeded: " << rot.npa_angle_max_deg << "° off C, I_d/C " << rot.id_over_c << ", roll/pitch/yaw " << rot.euler_max_deg[0] << ", "
                                << rot.euler_max_deg[1] << ", " << rot.euler_max_deg[2] << "°");
  BOOST_TEST(rot.tumbling);
  BOOST_TEST(rot.npa_angle_max_deg > 10);
  BOOST_TEST(rot.id_over_c < 0.999);
  BOOST_TEST(rot.short_axis_mode);
  // the same seed without the push stays within a hundredth of a degree
  const auto calm = observed(didymos("secondary:0,0,0.01", "2592000"));
  BOOST_TEST(calm.rotation[1].npa_angle_max_deg < 0.01);
}

BOOST_AUTO_TEST_SUITE_END()
