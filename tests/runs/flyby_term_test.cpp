// The planetary flyby (runs/src/binary_terms/flyby_term.cpp) against expectations computed here on
// their own: the perturber's position against this file's hyperbolic Kepler solve (the periapsis at
// t_q, a general point, vis-viva, v∞ far out, the orbit's plane); the pull on point masses against
// the plain difference of the two inverse squares; the force and the torques as the potential's
// derivatives; and the flyby against a direct integration of the same three point masses, from which
// the term departs by the binary's own quadrupole acting on the perturber's path (∝ μ/M at a fixed
// relative orbit) while its own effect is many orders larger.
#include <boost/test/unit_test.hpp>

#include <boost/multiprecision/float128.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "rotlie/models/odeint_warnings_off.hpp"
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include "rotlie/models/odeint_warnings_restore.hpp"

#include "rotlie/runs/binary_simulation.hpp"
#include "binary_term_checks.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/runs/user_input.hpp"

BOOST_AUTO_TEST_SUITE(flyby_term_test)

using namespace rotlie;
using test::pair_setup;
using test::rotation;
using test::term_potential;
using test::torque_gradient_error;

namespace {

using models::vec3;
using real = long double;
using quad = boost::multiprecision::float128;

constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180;
constexpr double earth = 5.9722e24;  // kg

struct flyby {
  double m, q, v_inf, i, node, peri, t_q;  // kg, km, km/s, degrees, s

  std::string text() const {
    std::ostringstream s;
    s.precision(17);
    s << m << ',' << q << ',' << v_inf << ',' << i << ',' << node << ',' << peri << ',' << t_q;
    return s.str();
  }
  std::vector<double> values() const { return {m, q, v_inf, i, node, peri, t_q}; }
};

template <class T>
using matrix = std::array<std::array<T, 3>, 3>;

template <class T>
vec3<T> turned_by(const matrix<T>& m, const vec3<T>& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2], m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

/// R₃(Ω) R₁(i) R₃(ω), written out from its three factors.
template <class T>
matrix<T> perifocal_to_inertial(const flyby& f) {
  const auto product = [](const matrix<T>& x, const matrix<T>& y) {
    matrix<T> z{};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) z[r][c] += x[r][k] * y[k][c];
    return z;
  };
  using std::cos;
  using std::sin;
  const T d = T(pi) / 180;  // π as the double holds it: the term is given degrees in double
  const T O = T(f.node) * d, i = T(f.i) * d, w = T(f.peri) * d;
  const matrix<T> Rz_O{{{cos(O), -sin(O), 0}, {sin(O), cos(O), 0}, {0, 0, 1}}};
  const matrix<T> Rx_i{{{1, 0, 0}, {0, cos(i), -sin(i)}, {0, sin(i), cos(i)}}};
  const matrix<T> Rz_w{{{cos(w), -sin(w), 0}, {sin(w), cos(w), 0}, {0, 0, 1}}};
  return product(product(Rz_O, Rx_i), Rz_w);
}

/// The perturber's position and velocity at t about GM = G(M + m), in T: e = 1 + q v∞²/GM, |a| = GM/v∞²,
/// the hyperbolic anomaly by bisection of e sinh H − H = n (t − t_q) (increasing in H, |H| ≤ asinh(|M|/(e − 1))).
template <class T>
std::array<vec3<T>, 2> hyperbola(const flyby& f, const T& GM, const T& t) {
  using std::abs;
  using std::asinh;
  using std::cosh;
  using std::sinh;
  using std::sqrt;
  const T v = T(f.v_inf), A = GM / (v * v), e = 1 + T(f.q) * v * v / GM, n = sqrt(GM / (A * A * A));
  const T M = n * (t - T(f.t_q));
  T lo = -asinh(abs(M) / (e - 1)) - 1, hi = -lo;
  for (int k = 0; k < 400; ++k) {
    const T mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    (e * sinh(mid) - mid < M ? lo : hi) = mid;
  }
  const T H = (lo + hi) / 2, rate = n / (e * cosh(H) - 1), b = A * sqrt(e * e - 1);
  const auto R = perifocal_to_inertial<T>(f);
  return {turned_by(R, vec3<T>{A * (e - cosh(H)), b * sinh(H), T(0)}), turned_by(R, vec3<T>{-A * sinh(H) * rate, b * cosh(H) * rate, T(0)})};
}

vec3<double> to_double(const vec3<real>& x) { return {static_cast<double>(x[0]), static_cast<double>(x[1]), static_cast<double>(x[2])}; }
vec3<double> scaled(const vec3<double>& x, double c) { return {c * x[0], c * x[1], c * x[2]}; }
vec3<double> minus(const vec3<double>& x, const vec3<double>& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }
double apart(const vec3<double>& x, const vec3<double>& y) { return models::norm(minus(x, y)); }
vec3<double> unit(const vec3<double>& x) { return scaled(x, 1 / models::norm(x)); }
vec3<double> vector_of(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }



std::shared_ptr<const runs::registered_term> flyby_for(const flyby& f, const models::binary_system<double>& sys) {
  return runs::binary_term_named("flyby")->make(f.values(), sys);
}


}  // namespace

BOOST_AUTO_TEST_CASE(the_perturber_is_on_its_hyperbola) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const auto& x = setup.start;
  const flyby f{earth, 30000, 6, 35, 110, 250, 5000};
  const auto term = flyby_for(f, sys);
  const real GM = real(setup.G) * (real(sys.total_mass()) + real(f.m));
  const auto R = perifocal_to_inertial<double>(f);
  const auto P_hat = turned_by(R, vec3<double>{1, 0, 0}), normal = turned_by(R, vec3<double>{0, 0, 1});
  // at t_q: q along the periapsis direction, moving across it at √(v∞² + 2GM/q)
  {
    const auto v = term->values(x, f.t_q);
    const auto P = vector_of(v["position"]), V = vector_of(v["velocity"]);
    const double v_q = std::sqrt(f.v_inf * f.v_inf + 2 * static_cast<double>(GM) / f.q);
    const double error = apart(P, scaled(P_hat, f.q)) / f.q, speed = std::abs(models::norm(V) - v_q) / v_q;
    BOOST_TEST_MESSAGE("at t_q: |P − q P̂|/q = " << error << ", |V| off √(v∞² + 2GM/q) by " << speed << " (relative)");
    BOOST_TEST(error < 1e-15);
    BOOST_TEST(speed < 1e-15);
    BOOST_TEST(std::abs(models::dot(V, P_hat)) < 1e-15 * v_q);
  }
  // anywhere, against this file's solve; vis-viva and the orbit's plane along the way
  double worst_position = 0, worst_velocity = 0, worst_energy = 0, worst_plane = 0;
  for (const double t : {-3e6, -2e5, -1e4, 0.0, 4999.0, 7000.0, 6e4, 1e6, 1e8}) {
    const auto v = term->values(x, t);
    const auto P = vector_of(v["position"]), V = vector_of(v["velocity"]);
    const auto expected = hyperbola<real>(f, GM, real(t));
    worst_position = std::max(worst_position, apart(P, to_double(expected[0])) / models::norm(P));
    worst_velocity = std::max(worst_velocity, apart(V, to_double(expected[1])) / models::norm(V));
    const double vis_viva = f.v_inf * f.v_inf + 2 * static_cast<double>(GM) / models::norm(P);
    worst_energy = std::max(worst_energy, std::abs(models::dot(V, V) - vis_viva) / vis_viva);
    worst_plane = std::max(worst_plane, std::abs(models::dot(P, normal)) / models::norm(P));
  }
  BOOST_TEST_MESSAGE("t from t_q − 3e6 s to 1e8 s: position off the Kepler solve by at most " << worst_position << ", velocity " << worst_velocity
                                                                                             << ", v² off v∞² + 2GM/|P| " << worst_energy
                                                                                             << ", out of the plane " << worst_plane << " (relative)");
  BOOST_TEST(worst_position < 1e-13);
  BOOST_TEST(worst_velocity < 1e-13);
  BOOST_TEST(worst_energy < 1e-13);
  BOOST_TEST(worst_plane < 1e-14);
  // far out the speed tends to v∞, and the perturber leaves along the outgoing asymptote
  const auto far = term->values(x, 1e12);
  const double speed = models::norm(vector_of(far["velocity"]));
  BOOST_TEST_MESSAGE("at t = 1e12 s: |V| − v∞ = " << speed - f.v_inf << " km/s, |P| = " << models::norm(vector_of(far["position"])) << " km");
  BOOST_TEST(std::abs(speed - f.v_inf) < 1e-6);
  for (const char* field : {"acceleration", "M1", "M2"})
    for (int k = 0; k < 3; ++k) BOOST_TEST(std::isfinite(far[field][k].get<double>()));
}

BOOST_AUTO_TEST_CASE(point_masses_feel_the_whole_difference) {
  // spheres: the figure's terms vanish (tr J = 3 dᵀJd/|d|²) and the pull is that on two points
  runs::binary_request r;
  r.primary = "ellipsoid:0.4,0.4,0.4", r.secondary = "ellipsoid:0.1,0.1,0.1", r.density = "2200", r.separation = "1.2";
  r.integrator = "SIER4", r.T = "0";
  const auto setup = runs::binary_setup_of(r);
  const auto sys = setup.system_model();
  const quad m1 = quad(sys.body(0).mass), m2 = quad(sys.body(1).mass), M = m1 + m2;
  double worst = 0, worst_torque = 0, size = 0;
  for (const double q : {3.0, 50.0, 3e4, 1e7}) {
    const flyby f{earth, q, 6, 20, 40, 60, 100};
    const auto term = flyby_for(f, sys);
    for (const double t : {0.0, 100.0, 5e3}) {
      models::binary_state<double> x = setup.start;
      x.r = {0.7, -0.9, 0.3};
      const auto v = term->values(x, t);
      const auto P = vector_of(v["position"]);
      // G m (d₂/|d₂|³ − d₁/|d₁|³) in float128 (the plain difference loses |P|/|r| of its 34 digits)
      vec3<quad> d1, d2;
      vec3<double> expected;
      for (std::size_t c = 0; c < 3; ++c) d1[c] = quad(P[c]) + m2 / M * quad(x.r[c]), d2[c] = quad(P[c]) - m1 / M * quad(x.r[c]);
      const quad n1 = sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]), n2 = sqrt(d2[0] * d2[0] + d2[1] * d2[1] + d2[2] * d2[2]);
      for (std::size_t c = 0; c < 3; ++c) expected[c] = static_cast<double>(quad(setup.G) * quad(f.m) * (d2[c] / (n2 * n2 * n2) - d1[c] / (n1 * n1 * n1)));
      const auto a = vector_of(v["acceleration"]);
      const double error = apart(a, expected) / models::norm(expected);
      worst = std::max(worst, error);
      // the torque's natural size: 3Gm/|d|³ times a moment
      const double scale = 3 * setup.G * f.m / std::pow(models::norm(P), 3) * sys.moments(0)[0];
      size = std::max(size, scale);
      worst_torque = std::max({worst_torque, models::norm(vector_of(v["M1"])) / scale, models::norm(vector_of(v["M2"])) / scale});
    }
  }
  BOOST_TEST_MESSAGE("spheres, |P| from 3 km to 1e7 km: the acceleration off G m (d₂/|d₂|³ − d₁/|d₁|³) by at most " << worst
                                                                                                             << " (relative); torques at most " << worst_torque
                                                                                                             << " of 3Gm/|d|³ A");
  BOOST_TEST(worst < 1e-12);
  BOOST_TEST(worst_torque < 1e-14);
}

BOOST_AUTO_TEST_CASE(force_and_torques_are_the_potentials_derivatives) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  double worst_F = 0, worst_M = 0;
  // near (the figure's share of the force some 1e-2) and far
  for (const double q : {6.0, 400.0}) {
    const flyby f{3e15, q, 0.01, 50, 120, 75, 300};
    const auto term = flyby_for(f, sys);
    const double t = 350;
    models::binary_state<double> x = setup.start;
    x.r = {0.9, -0.5, 0.4};
    x.body[0].Q = rotation(unit({1, 2, 3}), 0.7);
    x.body[1].Q = rotation(unit({-2, 1, 0.5}), 2.1);
    models::mutual_gravity<double> g;
    term->add(x, t, g);
    // fourth-order stencils in r and in a turn δ of body k about the inertial axis j, Q → R(δ ê_j) Q (U changes by −M_j δ)
    const double dr = 1e-3 * q / 6;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto U = [&](double delta) {
        auto y = x;
        y.r[k] += delta;
        return term_potential(*term, y, t);
      };
      const double slope = (8 * (U(dr) - U(-dr)) - (U(2 * dr) - U(-2 * dr))) / (12 * dr);
      worst_F = std::max(worst_F, std::abs(-slope - g.F[k]) / models::norm(g.F));
    }
    worst_M = std::max(worst_M, torque_gradient_error(*term, x, t, g));
  }
  BOOST_TEST_MESSAGE("F against −∂U/∂r: " << worst_F << "; M against −∂U/∂θ: " << worst_M << " (relative)");
  BOOST_TEST(worst_F < 1e-9);
  BOOST_TEST(worst_M < 1e-9);
}

namespace {

// Three point masses: the perturber seen from the binary's barycentre, R, and the relative orbit r.
// With d_k = R − x_k, x₁ = −(m₂/M) r, x₂ = (m₁/M) r:
//   R̈ = −G (M + m)/M Σ m_k d_k/|d_k|³,   r̈ = −G M r/|r|³ + G m (d₂/|d₂|³ − d₁/|d₁|³),
// exact (the barycentre's acceleration is taken off R̈ and cancels in r̈).
using three_body_state = std::array<real, 12>;  // R, Ṙ, r, ṙ

struct three_body {
  real G, m, m1, m2;

  void operator()(const three_body_state& y, three_body_state& dy, const real&) const {
    const real M = m1 + m2;
    std::array<real, 3> d1, d2;
    for (std::size_t k = 0; k < 3; ++k) d1[k] = y[k] + m2 / M * y[6 + k], d2[k] = y[k] - m1 / M * y[6 + k];
    const auto inverse_cube = [](const std::array<real, 3>& v) {
      const real n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      return 1 / (n * n * n);
    };
    const real c1 = inverse_cube(d1), c2 = inverse_cube(d2), cr = inverse_cube({y[6], y[7], y[8]});
    for (std::size_t k = 0; k < 3; ++k) {
      dy[k] = y[3 + k];
      dy[6 + k] = y[9 + k];
      dy[3 + k] = -G * (M + m) / M * (m1 * d1[k] * c1 + m2 * d2[k] * c2);
      dy[9 + k] = -G * M * y[6 + k] * cr + G * m * (d2[k] * c2 - d1[k] * c1);
    }
  }
};

/// r(T) of the three point masses from the perturber on the flyby's hyperbola at t = 0 and the
/// setup's r, v, by Runge–Kutta–Fehlberg's eighth-order solution at a fixed step.
vec3<double> three_body_r(const runs::binary_setup& s, const flyby& f, double T, long steps) {
  const auto sys = s.system_model();
  const three_body system{real(s.G), real(f.m), real(sys.body(0).mass), real(sys.body(1).mass)};
  const auto start = hyperbola<real>(f, real(s.G) * (real(sys.total_mass()) + real(f.m)), real(0));
  three_body_state y;
  for (std::size_t k = 0; k < 3; ++k) y[k] = start[0][k], y[3 + k] = start[1][k], y[6 + k] = s.start.r[k], y[9 + k] = s.start.v[k];
  boost::numeric::odeint::runge_kutta_fehlberg78<three_body_state, real, three_body_state, real> rk;
  const real h = real(T) / steps;
  for (long k = 0; k < steps; ++k) rk.do_step(system, y, h * k, h);
  return {static_cast<double>(y[6]), static_cast<double>(y[7]), static_cast<double>(y[8])};
}

/// Two spheres (point masses at any order) of masses m1, m2 on the circular start at `separation`.
runs::binary_setup spheres(double m1, double m2, double separation, const flyby* f, double T) {
  runs::binary_request r;
  const auto radius = [](double m) { return std::cbrt(m / (2000e9 * 4 * pi / 3)); };
  const auto sphere = [](double R) {
    std::ostringstream s;
    s.precision(17);
    s << "ellipsoid:" << R << ',' << R << ',' << R;
    return s.str();
  };
  std::ostringstream masses, distance;
  masses.precision(17), distance.precision(17);
  masses << m1 << ',' << m2, distance << separation;
  r.primary = sphere(radius(m1)), r.secondary = sphere(radius(m2)), r.mass = masses.str(), r.separation = distance.str();
  r.order = "0", r.integrator = "odeint-rkf78:1e-13", r.h = "60", r.T = std::to_string(static_cast<long>(T));
  if (f) r.terms["flyby"] = f->text();
  return runs::binary_setup_of(r);
}

struct comparison {
  double departure, effect, reference_error, floor;
};

comparison against_three_bodies(double m1, double m2, double separation, const flyby& f, double T, long steps) {
  const auto alone_setup = spheres(m1, m2, separation, nullptr, T);
  const auto alone = runs::binary_run(alone_setup).end.x.r;
  const auto setup = spheres(m1, m2, separation, &f, T);
  const auto with = runs::binary_run(setup).end.x.r;
  const auto reference = three_body_r(setup, f, T, steps);
  flyby none = f;
  none.m = 0;
  return {apart(with, reference), apart(with, alone), apart(reference, three_body_r(setup, f, T, steps / 2)),
          apart(alone, three_body_r(alone_setup, none, T, steps))};
}

}  // namespace

BOOST_AUTO_TEST_CASE(against_three_point_masses) {
  // the Didymos pair as point masses (its masses and 1.19 km orbit) and the Earth at Apophis's 2029
  // encounter (38,000 km, v∞ 5.84 km/s), closest a day in
  {
    const flyby f{earth, 38000, 5.84, 45, 30, 60, 86400};
    const auto c = against_three_bodies(5.4e11, 4.9e9, 1.19, f, 2 * 86400, 5760);
    BOOST_TEST_MESSAGE("Earth past Didymos at 38,000 km: |r − r_3body| = " << c.departure << " km, the flyby's effect |r − r_alone| = " << c.effect
                                                                           << " km; the reference at 60 s off by " << c.reference_error
                                                                           << " km, rotlie without the flyby off the two-body reference by " << c.floor << " km");
    BOOST_TEST(c.effect > 1e-3);
    BOOST_TEST(c.departure < 1e-7 * c.effect);
    BOOST_TEST(c.reference_error < 1e-7 * c.effect);
  }
  // a close flyby where the model's neglect shows: a 400 km body 45 km from a pair 1.5 km apart; the
  // same total mass split 1:1 and 10:1, the relative orbit's equations (to their octupole) the same
  const double M = 4.5e11, T = 4.2e5;
  const flyby f{4e14, 45, 9e-4, 30, 20, 80, T / 2};
  const auto equal = against_three_bodies(M / 2, M / 2, 1.5, f, T, 8400);
  const auto unequal = against_three_bodies(M * 10 / 11, M / 11, 1.5, f, T, 8400);
  const double mu_ratio = (0.5 * 0.5) / (10.0 / 121);
  for (const auto& [name, c] : {std::pair{"1:1", equal}, std::pair{"10:1", unequal}})
    BOOST_TEST_MESSAGE("masses " << name << ": |r − r_3body| = " << c.departure << " km, the flyby's effect " << c.effect << " km (ratio "
                                 << c.effect / c.departure << "); the reference at 100 s off by " << c.reference_error << " km, the floor " << c.floor
                                 << " km");
  const double ratio = equal.departure / unequal.departure;
  BOOST_TEST_MESSAGE("departure 1:1 over 10:1: " << ratio << " (μ/M: " << mu_ratio << "); effects " << equal.effect << ", " << unequal.effect << " km");
  BOOST_TEST(ratio > 0.8 * mu_ratio);
  BOOST_TEST(ratio < 1.25 * mu_ratio);
  for (const auto& c : {equal, unequal}) {
    BOOST_TEST(c.departure < 1e-2 * c.effect);
    BOOST_TEST(c.reference_error < c.departure / 100);
    BOOST_TEST(c.floor < c.departure / 100);
  }
}

BOOST_AUTO_TEST_CASE(bad_values_are_refused_naming_the_option) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const auto* term = runs::binary_term_named("flyby");
  BOOST_REQUIRE(term);
  const double nan = std::nan(""), inf = HUGE_VAL;
  const std::vector<std::vector<double>> bad{
      {earth, 3e4, 6, 0, 0, 0},         {-1, 3e4, 6, 0, 0, 0, 0},   {earth, 0, 6, 0, 0, 0, 0},   {earth, -5, 6, 0, 0, 0, 0},
      {earth, 3e4, 0, 0, 0, 0, 0},      {earth, 3e4, -6, 0, 0, 0, 0}, {nan, 3e4, 6, 0, 0, 0, 0}, {earth, inf, 6, 0, 0, 0, 0},
      {earth, 3e4, nan, 0, 0, 0, 0},    {earth, 3e4, 6, inf, 0, 0, 0}, {earth, 3e4, 6, 0, 0, 0, nan}};
  for (const auto& values : bad) {
    try {
      term->make(values, sys);
      BOOST_ERROR("accepted a bad flyby");
    } catch (const runs::bad_input& e) {
      const std::string what = e.what();
      BOOST_TEST(what.find("--flyby") != std::string::npos);
      BOOST_TEST(what.find('\n') == std::string::npos);
    }
  }
  BOOST_CHECK_NO_THROW(term->make({0, 3e4, 6, 0, 0, 0, 0}, sys));
}

// A planet by name is its mass: `earth` reads as 5.9722e24 kg (any case), in the mass's place only.
BOOST_AUTO_TEST_CASE(a_planet_by_name_is_its_mass) {
  const auto* term = runs::binary_term_named("flyby");
  BOOST_REQUIRE(term);
  BOOST_TEST(runs::with_named_values(*term, "Earth,38000,5.84,45,30,60,86400") == "5.9722e+24,38000,5.84,45,30,60,86400");
  BOOST_TEST(runs::with_named_values(*term, " jupiter ,1e6,10,0,0,0,0").substr(0, 12) == "1.89813e+27,");
  BOOST_TEST(runs::with_named_values(*term, "5,earth,1,0,0,0,0") == "5,earth,1,0,0,0,0");  // not a distance
  BOOST_CHECK_EXCEPTION(runs::with_named_values(*term, "pluto,38000,5.84,45,30,60,86400"), runs::bad_input, [](const runs::bad_input& e) {
    return std::string(e.what()) == "--flyby: m 'pluto' is neither a number nor one of earth, moon, mars, venus, jupiter";
  });
  runs::binary_request by_name, by_number;
  for (auto* r : {&by_name, &by_number}) {
    r->system = "didymos", r->integrator = "SIER4", r->h = "60", r->T = "600";
  }
  by_name.terms["flyby"] = "earth,38000,5.84,45,30,60,86400";
  by_number.terms["flyby"] = "5.9722e24,38000,5.84,45,30,60,86400";
  const auto a = runs::binary_run(runs::binary_setup_of(by_name)), b = runs::binary_run(runs::binary_setup_of(by_number));
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(a.end.x.r[k] == b.end.x.r[k]);
}

BOOST_AUTO_TEST_SUITE_END()
