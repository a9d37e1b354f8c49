// `rotlie binary --order 0` with a Kepler split on open and nearly radial orbits: at order 0 the kicks
// vanish and each step is the exact drift, so the end must be Kepler's closed form (the float128
// reference of tests/models) for any step. These runs stopped with "the universal anomaly did not
// converge" (exit 1) before the drift's solver was bracketed (the first three of these did).
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"
#include "../models/kepler_reference.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

BOOST_AUTO_TEST_SUITE(binary_kepler_cli_test)

using namespace rotlie::test_cli;

namespace {

// the bodies' masses as rotlie computes them (density 2000 kg/m³), and GM of the pair
const double pi = std::acos(-1.0);
const double M1 = 2000 * 1e9 * 4 * pi / 3 * 0.4 * 0.38 * 0.35, M2 = 2000 * 1e9 * 4 * pi / 3 * 0.1 * 0.08 * 0.06;

// a conic of pericentre q (km) and eccentricity e at true anomaly f0, tilted by 0.3 rad about x
std::pair<rotlie::models::vec3<double>, rotlie::models::vec3<double>> conic(double GM, double q, double e, double f0) {
  const double p = q * (1 + e), rr = p / (1 + e * std::cos(f0));
  const double vr = std::sqrt(GM / p) * e * std::sin(f0), vt = std::sqrt(GM / p) * (1 + e * std::cos(f0));
  const double c = std::cos(f0), s = std::sin(f0), ct = std::cos(0.3), st = std::sin(0.3);
  return {{rr * c, ct * rr * s, st * rr * s}, {vr * c - vt * s, ct * (vr * s + vt * c), st * (vr * s + vt * c)}};
}

}  // namespace

BOOST_AUTO_TEST_CASE(open_and_nearly_radial_orbits_run_at_any_step_and_match_keplers_equation) {
  const double G = 6.6743e-20, GM = G * (M1 + M2);
  struct kind {
    const char* name;
    double e, f0, h, tolerance;  // tolerance: 64 ε times the case's condition number, rounded up
  };
  const double a = 0.6 / (1 - 0.9), P = 2 * pi * std::sqrt(a * a * a / GM);
  for (const auto& k : {kind{"hyperbola e = 3, 1e6 / n per step", 3.0, 0.0, 9.48e8, 1e-13}, kind{"hyperbola e = 1.5 inbound", 1.5, -1.15, 7.59e9, 1e-13},
                        kind{"parabola", 1.0, -1.5, 1e6, 1e-13}, kind{"ellipse e = 0.9, 1000.41 periods per step", 0.9, 2.0, std::round(1000.41 * P), 1e-8}}) {
    const auto [r, v] = conic(GM, 0.6, k.e, k.f0);  // pericentre 0.6 km: outside both bodies
    const auto path = fs::temp_directory_path() / ("rotlie-kepler-" + std::to_string(::getpid()) + ".json");
    std::ofstream(path) << nlohmann::json{{"r", r}, {"v", v}, {"Q1", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {"Q2", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                                          {"omega1", {0, 0, 0}}, {"omega2", {0, 0, 0}}}
                                              .dump(-1, ' ', false, nlohmann::json::error_handler_t::strict);
    char h[64], T[64];
    std::snprintf(h, sizeof h, "%.17g", k.h);
    std::snprintf(T, sizeof T, "%.17g", 3 * k.h);
    const auto out = run(std::string("binary --primary ellipsoid:0.4,0.38,0.35 --secondary ellipsoid:0.1,0.08,0.06 --density 2000 --order 0 --integrator KEPLER4 --h ") + h +
                         " --T " + T + " --state " + path.string() + " --json");
    fs::remove(path);
    BOOST_TEST_REQUIRE(out.status == 0, k.name << ": " << out.err);
    const auto j = nlohmann::json::parse(out.out);
    rotlie::models::vec3<rotlie::quad> rq{r[0], r[1], r[2]}, vq{v[0], v[1], v[2]};
    rotlie::test::kepler_reference(rq, vq, rotlie::quad(GM), rotlie::quad(3 * k.h));
    double d = 0, n = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double ref = static_cast<double>(rq[i]);
      d += (j["r"][i].get<double>() - ref) * (j["r"][i].get<double>() - ref), n += ref * ref;
    }
    BOOST_TEST_MESSAGE(k.name << ": relative distance from Kepler's equation " << std::sqrt(d / n));
    BOOST_TEST(std::sqrt(d / n) <= k.tolerance, k.name << ": " << std::sqrt(d / n));
  }
}

BOOST_AUTO_TEST_SUITE_END()
