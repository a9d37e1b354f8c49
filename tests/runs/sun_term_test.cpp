// The Sun's tide on the binary (runs/src/binary_terms/sun_term.cpp) against expectations computed
// here on their own: the Sun's position against a Kepler solve of this file (perihelion, a circular
// orbit's uniform turn, a general point), Hill's pull along and across the Sun's direction, the
// torque on a body turned in a principal plane, the force and the torques as the potential's
// derivatives; Hill's problem on a circular heliocentric orbit, whose Jacobi integral
// E − n n̂·L holds to round-off under a tight Runge–Kutta and stays bounded under the splittings; and
// the Sun as a third point mass integrated in float128, from which the term departs by the next
// order of |r|/|S| (∝ |S|⁻⁴) while its own effect is some |S|/|r| times larger.
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

BOOST_AUTO_TEST_SUITE(sun_term_test)

using namespace rotlie;
using test::pair_setup;
using test::rotation;
using test::term_potential;
using test::torque_gradient_error;

namespace {

using models::vec3;
using quad = boost::multiprecision::float128;

// the units the term documents: km, s
constexpr double GM_sun = 1.32712440018e11;  // km³ s⁻²
constexpr double au = 149597870.7;           // km
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180;

struct elements {
  double a_au, e, i, node, peri, M0;  // AU, then degrees

  std::string text() const {
    std::ostringstream s;
    s.precision(17);
    s << a_au << ',' << e << ',' << i << ',' << node << ',' << peri << ',' << M0;
    return s.str();
  }
  double a() const { return a_au * au; }
  double n() const { return std::sqrt(GM_sun / (a() * a() * a())); }
  /// The heliocentric orbit's normal: R₃(Ω) R₁(i) ẑ.
  vec3<double> normal() const { return {std::sin(node * deg) * std::sin(i * deg), -std::cos(node * deg) * std::sin(i * deg), std::cos(i * deg)}; }
};

template <class T>
using matrix = std::array<std::array<T, 3>, 3>;

template <class T>
matrix<T> product(const matrix<T>& x, const matrix<T>& y) {
  matrix<T> z{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) z[r][c] += x[r][k] * y[k][c];
  return z;
}

template <class T>
vec3<T> turned_by(const matrix<T>& m, const vec3<T>& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2], m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// elementary turns by θ about x and z
template <class T>
matrix<T> turn_x(const T& c, const T& s) {
  return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}
template <class T>
matrix<T> turn_z(const T& c, const T& s) {
  return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

/// The barycentre's heliocentric position and velocity at t, in T: the eccentric anomaly by
/// bisection of Kepler's equation (monotonic in E, |E − M| ≤ e), the perifocal point turned by
/// R₃(Ω) R₁(i) R₃(ω) as three matrices.
template <class T>
std::array<vec3<T>, 2> barycentre(const elements& el, const T& t) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T a = T(el.a_au) * T(au), e = T(el.e), GM = T(GM_sun), n = sqrt(GM / (a * a * a));
  const T d = T(pi) / 180;  // π as the double holds it: the term is given degrees in double
  const T M = T(el.M0) * d + n * t;
  T lo = M - 1, hi = M + 1;
  for (int k = 0; k < 400; ++k) {
    const T mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    (mid - e * sin(mid) < M ? lo : hi) = mid;
  }
  const T E = (lo + hi) / 2, c = cos(E), s = sin(E), root = sqrt(1 - e * e), rate = n / (1 - e * c);
  const T inc = T(el.i) * d, node = T(el.node) * d, peri = T(el.peri) * d;
  const auto R = product(product(turn_z<T>(cos(node), sin(node)), turn_x<T>(cos(inc), sin(inc))), turn_z<T>(cos(peri), sin(peri)));
  return {turned_by(R, vec3<T>{a * (c - e), a * root * s, T(0)}), turned_by(R, vec3<T>{-a * s * rate, a * root * c * rate, T(0)})};
}

/// S(t) = −X(t) in double.
vec3<double> sun_expected(const elements& el, double t) {
  const auto X = barycentre<long double>(el, t)[0];
  return {-static_cast<double>(X[0]), -static_cast<double>(X[1]), -static_cast<double>(X[2])};
}

vec3<double> scaled(const vec3<double>& x, double c) { return {c * x[0], c * x[1], c * x[2]}; }
double apart(const vec3<double>& x, const vec3<double>& y) { return models::norm(vec3<double>{x[0] - y[0], x[1] - y[1], x[2] - y[2]}); }

vec3<double> vector_of(const nlohmann::json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }


vec3<double> unit(const vec3<double>& x) { return scaled(x, 1 / models::norm(x)); }


std::shared_ptr<const runs::registered_term> sun_for(const elements& el, const models::binary_system<double>& sys) {
  std::vector<double> values{el.a_au, el.e, el.i, el.node, el.peri, el.M0};
  return runs::binary_term_named("sun")->make(values, sys);
}


}  // namespace

BOOST_AUTO_TEST_CASE(the_sun_is_on_its_kepler_orbit_seen_from_the_barycentre) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const models::binary_state<double> x = setup.start;
  // M0 = 0 at t = 0: the perihelion, a(1 − e) from the Sun, so S = −a(1 − e) P̂, P̂ = R₃(Ω)R₁(i)R₃(ω) x̂
  {
    const elements el{0.3, 0.4, 25, 70, 110, 0};
    const auto S = vector_of(sun_for(el, sys)->values(x, 0)["position"]);
    const auto turn = [](double angle_deg) { return std::array<double, 2>{std::cos(angle_deg * deg), std::sin(angle_deg * deg)}; };
    const auto [cO, sO] = turn(el.node);
    const auto [ci, si] = turn(el.i);
    const auto [cw, sw] = turn(el.peri);
    const auto R = product(product(turn_z(cO, sO), turn_x(ci, si)), turn_z(cw, sw));
    const auto P = turned_by(R, vec3<double>{1, 0, 0});
    const double error = apart(S, scaled(P, -el.a() * (1 - el.e))) / models::norm(S);
    BOOST_TEST_MESSAGE("perihelion: |S − (−a(1 − e)P̂)|/|S| = " << error);
    BOOST_TEST(error < 1e-15);
  }
  // e = 0: |S| = a, and S turns about the orbit's normal n̂ at n = √(GM/a³)
  {
    const elements el{0.5, 0, 30, 40, 50, 20};
    const auto term = sun_for(el, sys);
    const auto S0 = vector_of(term->values(x, 0)["position"]);
    const auto N = el.normal();
    double worst_radius = 0, worst_angle = 0;
    for (const double t : {1e5, 1.3e6, 7.7e6, 3.1e7, 1e9}) {
      const auto S = vector_of(term->values(x, t)["position"]);
      worst_radius = std::max(worst_radius, std::abs(models::norm(S) - el.a()) / el.a());
      const double turned = std::atan2(models::dot(N, models::cross(S0, S)), models::dot(S0, S));
      const double expected = std::remainder(el.n() * t, 2 * pi);
      worst_angle = std::max(worst_angle, std::abs(std::remainder(turned - expected, 2 * pi)));
      BOOST_TEST(std::abs(models::dot(N, S)) < 1e-14 * el.a());
    }
    BOOST_TEST_MESSAGE("circular orbit: |S| − a at most " << worst_radius << " a; the turn about n̂ off n·t by at most " << worst_angle << " rad");
    BOOST_TEST(worst_radius < 1e-15);
    // n·t reaches 560 rad: its round-off, some 10⁻¹³ rad, is the floor
    BOOST_TEST(worst_angle < 1e-12);
  }
  // anywhere on an eccentric inclined orbit, against this file's Kepler solve
  {
    const elements el{1.2, 0.6, 40, 200, 300, 75};
    const auto term = sun_for(el, sys);
    double worst = 0;
    for (const double t : {0.0, 1e6, 4.4e6, 3e7, 2e8}) {
      const auto S = vector_of(term->values(x, t)["position"]);
      worst = std::max(worst, apart(S, sun_expected(el, t)) / models::norm(S));
    }
    BOOST_TEST_MESSAGE("e = 0.6: |S − S_Kepler|/|S| at most " << worst);
    BOOST_TEST(worst < 1e-13);
  }
}

BOOST_AUTO_TEST_CASE(hills_pull_along_and_across_the_sun) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const elements el{0.1, 0.3, 15, 80, 20, 130};
  const auto term = sun_for(el, sys);
  const double t = 2.5e6;
  const auto S = sun_expected(el, t), u = unit(S);
  const double GM_S3 = GM_sun / std::pow(models::norm(S), 3);
  models::binary_state<double> x = setup.start;
  // along Ŝ: stretched, a = 2GM|r|/|S|³ Ŝ
  x.r = scaled(u, 1.3);
  const auto along = vector_of(term->values(x, t)["acceleration"]);
  const double e_along = apart(along, scaled(u, 2 * GM_S3 * 1.3)) / (2 * GM_S3 * 1.3);
  // across Ŝ: squeezed, a = −GM r/|S|³
  const auto w = unit(models::cross(u, vec3<double>{0.3, -0.2, 0.9}));
  x.r = scaled(w, 0.8);
  const auto across = vector_of(term->values(x, t)["acceleration"]);
  const double e_across = apart(across, scaled(w, -GM_S3 * 0.8)) / (GM_S3 * 0.8);
  BOOST_TEST_MESSAGE("Hill's pull: along Ŝ off 2GM r/|S|³ by " << e_along << ", across off −GM r/|S|³ by " << e_across << " (relative)");
  BOOST_TEST(e_along < 1e-14);
  BOOST_TEST(e_across < 1e-14);
}

BOOST_AUTO_TEST_CASE(the_torque_on_a_body_turned_in_a_principal_plane) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const elements el{0.2, 0.1, 35, 10, 60, 250};
  const auto term = sun_for(el, sys);
  const double t = 4e5;
  const auto S = sun_expected(el, t), u = unit(S);
  const double GM_S3 = GM_sun / std::pow(models::norm(S), 3);
  // an inertial frame whose first axis points at the Sun
  const auto f1 = unit(models::cross(u, vec3<double>{0.2, 0.7, -0.4})), f2 = models::cross(u, f1);
  const std::array<vec3<double>, 3> frame{u, f1, f2};
  double worst_aligned = 0, worst_turned = 0;
  for (int body = 0; body < 2; ++body)
    for (int a = 0; a < 3; ++a) {
      // principal axes a, b, c cyclic (right-handed); at θ = 0 axis a points at the Sun
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      models::mat3<double> Q0;
      for (int k = 0; k < 3; ++k) Q0(k, a) = frame[0][static_cast<std::size_t>(k)], Q0(k, b) = frame[1][static_cast<std::size_t>(k)], Q0(k, c) = frame[2][static_cast<std::size_t>(k)];
      const auto& I = sys.moments(body);
      const double Ia = I[static_cast<std::size_t>(a)], Ib = I[static_cast<std::size_t>(b)];
      const double scale = 3 * GM_S3 * std::abs(Ia - Ib);
      vec3<double> axis_c{};
      axis_c[static_cast<std::size_t>(c)] = 1;
      for (const double theta : {0.0, 0.3, 1.1, -2.0}) {
        models::binary_state<double> x = setup.start;
        // the body turned by θ about its axis c: axis a is θ away from Ŝ in the plane a–b
        x.body[body].Q = Q0 * rotation(axis_c, theta);
        const auto v = term->values(x, t);
        const auto M = vector_of(v[body == 0 ? "M1" : "M2"]);
        // the restoring sense: with Ia < Ib (a the longer axis) the torque turns axis a back to the Sun
        const auto expected = scaled(Q0 * axis_c, scale / std::abs(Ia - Ib) * (Ia - Ib) * std::sin(theta) * std::cos(theta));
        const double error = apart(M, expected) / scale;
        double& worst = theta == 0 ? worst_aligned : worst_turned;
        worst = std::max(worst, error);
      }
    }
  BOOST_TEST_MESSAGE("torque: aligned " << worst_aligned << ", turned off 3GM/|S|³ (Ia − Ib) sinθ cosθ by " << worst_turned << " (of 3GM/|S|³ |Ia − Ib|)");
  BOOST_TEST(worst_aligned < 1e-14);
  BOOST_TEST(worst_turned < 1e-14);
}

BOOST_AUTO_TEST_CASE(force_and_torques_are_the_potentials_derivatives) {
  const auto setup = pair_setup();
  const auto sys = setup.system_model();
  const elements el{0.05, 0.2, 50, 120, 75, 300};
  const auto term = sun_for(el, sys);
  const double t = 1.7e6;
  models::binary_state<double> x = setup.start;
  x.r = {0.9, -0.5, 0.4};
  x.body[0].Q = rotation(unit({1, 2, 3}), 0.7);
  x.body[1].Q = rotation(unit({-2, 1, 0.5}), 2.1);
  models::mutual_gravity<double> f;
  term->add(x, t, f);
  // U is quadratic in r: a central difference is exact but for round-off
  const double dr = 1e-2;
  double worst_F = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    auto ahead = x, behind = x;
    ahead.r[k] += dr, behind.r[k] -= dr;
    const double slope = (term_potential(*term, ahead, t) - term_potential(*term, behind, t)) / (2 * dr);
    worst_F = std::max(worst_F, std::abs(-slope - f.F[k]) / models::norm(f.F));
  }
  // a turn δ of body k about the inertial axis j, Q → R(δ ê_j) Q, changes U by −M_j δ (a fourth-order stencil)
  const double worst_M = torque_gradient_error(*term, x, t, f);
  BOOST_TEST_MESSAGE("F against −∂U/∂r: " << worst_F << "; M against −∂U/∂θ: " << worst_M << " (relative)");
  // round-off: U's ε over the difference's step (the stencil's δ⁴ term is below it)
  BOOST_TEST(worst_F < 1e-12);
  BOOST_TEST(worst_M < 1e-10);
}

namespace {

struct jacobi_record {
  double first = 0, last = 0, whole = 0;  // max |C − C₀|/|C₀| over the first third, the last third, the run
  double energy = 0;                      // max |E − E₀|/|C₀|: what −n n̂·L takes away
  double upright = 0;                     // the same for E − n ẑ·L: the axis matters too
  double hill_ratio = 0;                  // |r₀| / r_H
};

/// Didymos under a Sun on a circular orbit: C = E(x, t) − n n̂·L(x) along the run, sampled every `every` s.
jacobi_record jacobi_along(const std::string& integrator, const std::string& h, double T, double every, const elements& el) {
  runs::binary_request r;
  r.system = "didymos", r.integrator = integrator, r.h = h, r.T = std::to_string(static_cast<long>(T));
  r.terms["sun"] = el.text();
  const auto setup = runs::binary_setup_of(r);
  runs::binary_simulation sim(setup);
  const auto N = el.normal();
  const double n = el.n();
  const auto C = [&] { return sim.system().energy(sim.state(), sim.t()) - n * models::dot(N, sim.system().angular_momentum(sim.state())); };
  const auto upright = [&] { return sim.system().energy(sim.state(), sim.t()) - n * sim.system().angular_momentum(sim.state())[2]; };
  const double C0 = C(), E0 = sim.system().energy(sim.state(), 0), upright0 = upright();
  jacobi_record out;
  const double M_sun = GM_sun / setup.G;
  out.hill_ratio = models::norm(setup.start.r) / (el.a() * std::cbrt(sim.system().total_mass() / (3 * M_sun)));
  const long samples = std::lround(T / every);
  for (long k = 1; k <= samples; ++k) {
    sim.integrate(static_cast<double>(k) * every);
    const double dC = std::abs(C() - C0) / std::abs(C0);
    out.whole = std::max(out.whole, dC);
    if (3 * k <= samples) out.first = std::max(out.first, dC);
    if (3 * k > 2 * samples) out.last = std::max(out.last, dC);
    out.energy = std::max(out.energy, std::abs(sim.system().energy(sim.state(), sim.t()) - E0) / std::abs(C0));
    out.upright = std::max(out.upright, std::abs(upright() - upright0) / std::abs(C0));
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(hills_problem_keeps_its_jacobi_integral) {
  // e = 0 and an inclined orbit: the Sun turns uniformly about n̂, and in the frame turning with it
  // the problem is autonomous
  const elements el{0.08, 0, 30, 40, 60, 10};
  const double day = 86400;
  {
    const auto j = jacobi_along("odeint-rkf78:1e-14", "1200", 4 * day, 1200, el);
    BOOST_TEST_MESSAGE("Hill: |r₀|/r_H = " << j.hill_ratio << "; odeint-rkf78:1e-14 over 8 mutual orbits: |ΔC|/|C| at most " << j.whole
                                            << ", while |ΔE|/|C| reaches " << j.energy << " and that of E − n ẑ·L " << j.upright);
    BOOST_TEST(j.hill_ratio > 0.1);
    BOOST_TEST(j.hill_ratio < 0.5);
    BOOST_TEST(j.whole < 1e-13);
    // E alone is not conserved, nor E − n ẑ·L about the wrong axis: the check is not vacuous
    BOOST_TEST(j.energy > 1e6 * j.whole);
    BOOST_TEST(j.upright > 1e3 * j.whole);
  }
  for (const char* integrator : {"SIER4", "KEPLER4"}) {
    const auto j = jacobi_along(integrator, "120", 10 * day, 600, el);
    BOOST_TEST_MESSAGE(integrator << " h = 120 s over 20 mutual orbits: max |ΔC|/|C| " << j.first << " over the first third, " << j.last
                                  << " over the last (|ΔE|/|C| " << j.energy << ")");
    BOOST_TEST_INFO(integrator);
    // a drift linear in t would make the last third's maximum 3 times the first's at least
    BOOST_TEST(j.last < 1.5 * j.first);
    BOOST_TEST(j.energy > 100 * j.whole);
  }
}

namespace {

// The Sun and the two bodies as three point masses, heliocentric: the barycentre X and r = x₂ − x₁.
// The Sun's pull on each body is evaluated whole and differenced in float128 (34 digits): the tide
// is ~10⁻⁷ of each pull and the next order ~10⁻¹⁴, which double would leave at a few digits.
using three_body_state = std::array<quad, 12>;  // X, Ẋ, r, ṙ

struct three_body {
  quad GM, Gm1, Gm2;  // the Sun's, the bodies'

  void operator()(const three_body_state& y, three_body_state& dy, const quad&) const {
    const quad Gm = Gm1 + Gm2;
    std::array<quad, 3> x1, x2, g1, g2;
    for (std::size_t k = 0; k < 3; ++k) x1[k] = y[k] - Gm2 / Gm * y[6 + k], x2[k] = y[k] + Gm1 / Gm * y[6 + k];
    const auto inverse_cube = [](const std::array<quad, 3>& v) {
      const quad d = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      return 1 / (d * d * d);
    };
    const quad c1 = inverse_cube(x1), c2 = inverse_cube(x2), cr = inverse_cube({y[6], y[7], y[8]});
    for (std::size_t k = 0; k < 3; ++k) g1[k] = x1[k] * c1, g2[k] = x2[k] * c2;
    for (std::size_t k = 0; k < 3; ++k) {
      dy[k] = y[3 + k];
      dy[6 + k] = y[9 + k];
      // the bodies' pulls on the Sun (the heliocentric frame's acceleration) join the barycentre's
      dy[3 + k] = -(GM + Gm) / Gm * (Gm1 * g1[k] + Gm2 * g2[k]);
      dy[9 + k] = -GM * (g2[k] - g1[k]) - Gm * y[6 + k] * cr;
    }
  }
};

/// r(T) of the three point masses from the barycentre on the elements' orbit and the setup's r, v,
/// by Runge–Kutta–Fehlberg's eighth-order solution at a fixed step.
vec3<double> three_body_r(const runs::binary_setup& s, const elements& el, double sun_GM, double T, long steps) {
  const auto sys = s.system_model();
  const three_body f{quad(sun_GM), quad(s.G) * quad(sys.body(0).mass), quad(s.G) * quad(sys.body(1).mass)};
  const auto X = barycentre<quad>(el, quad(0));
  three_body_state y;
  for (std::size_t k = 0; k < 3; ++k) y[k] = X[0][k], y[3 + k] = X[1][k], y[6 + k] = s.start.r[k], y[9 + k] = s.start.v[k];
  boost::numeric::odeint::runge_kutta_fehlberg78<three_body_state, quad, three_body_state, quad> rk;
  const quad h = quad(T) / steps;
  quad t = 0;
  for (long k = 0; k < steps; ++k) {
    rk.do_step(f, y, t, h);
    t = h * (k + 1);
  }
  return {static_cast<double>(y[6]), static_cast<double>(y[7]), static_cast<double>(y[8])};
}

runs::binary_setup point_mass_run(const elements* sun, const std::string& integrator, double T) {
  runs::binary_request r;
  r.system = "didymos", r.order = "0", r.integrator = integrator, r.h = "3600", r.T = std::to_string(static_cast<long>(T));
  if (sun) r.terms["sun"] = sun->text();
  return runs::binary_setup_of(r);
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_sun_as_a_third_point_mass) {
  const double T = 86400;  // about two mutual orbits
  const std::string integrator = "odeint-rkf78:1e-14";
  const long steps = 1440;  // the reference's fixed step, 60 s
  const elements near{0.15, 0.1, 20, 50, 30, 40};
  elements far = near;
  far.a_au *= 2;
  // the floor: rotlie's run against the reference without the Sun (GM = 0: the bodies' orbit alone)
  const auto setup_alone = point_mass_run(nullptr, integrator, T);
  const auto alone = runs::binary_run(setup_alone).end.x.r;
  const double floor = apart(alone, three_body_r(setup_alone, near, 0, T, steps));
  double departure[2], effect[2], reference_error[2], size_ratio[2];
  for (int k = 0; k < 2; ++k) {
    const auto& el = k == 0 ? near : far;
    const auto setup = point_mass_run(&el, integrator, T);
    const auto with_sun = runs::binary_run(setup).end.x.r;
    const auto reference = three_body_r(setup, el, GM_sun, T, steps);
    reference_error[k] = apart(reference, three_body_r(setup, el, GM_sun, T, steps / 2));
    departure[k] = apart(with_sun, reference);
    effect[k] = apart(with_sun, alone);
    size_ratio[k] = el.a() / models::norm(setup.start.r);
    BOOST_TEST_MESSAGE("a = " << el.a_au << " AU: |r − r_3body| = " << departure[k] << " km, the Sun's effect |r − r_alone| = " << effect[k]
                              << " km (ratio " << effect[k] / departure[k] << "); the reference at 120 s off by " << reference_error[k]
                              << " km, rotlie without the Sun off the two-body reference by " << floor << " km");
  }
  const double ratio = departure[0] / departure[1];
  BOOST_TEST_MESSAGE("departure at a over departure at 2a: " << ratio << " (|S|⁻⁴: 16)");
  BOOST_TEST(ratio > 12);
  BOOST_TEST(ratio < 20);
  for (int k = 0; k < 2; ++k) {
    // the departure is the next order: |r|/|S| of the effect, give or take a factor of 10
    BOOST_TEST(effect[k] > 0.1 * size_ratio[k] * departure[k]);
    // both errors of the comparison are far below what it measures
    BOOST_TEST(reference_error[k] < departure[k] / 100);
  }
  BOOST_TEST(floor < departure[1] / 100);
}

BOOST_AUTO_TEST_SUITE_END()
