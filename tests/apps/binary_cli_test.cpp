// `rotlie binary` end to end: the JSON contract (issue 33) and the start's values at --T 0 against
// closed forms, every integrator family on the Didymos system against a tight RKF78 run, a run
// continued from its own output, a polyhedron against the ellipsoid it approximates, bodies that
// touch in mid-run (exit 1, saying when), and bad input as one line with exit status 2.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <fstream>
#include <sstream>
#include <vector>
#include <nlohmann/json.hpp>
#include <string>

BOOST_AUTO_TEST_SUITE(binary_cli_test)

using namespace rotlie::test_cli;

namespace {

nlohmann::json binary_json(const std::string& args) {
  const auto r = run("binary " + args + " --json");
  BOOST_TEST_REQUIRE(r.status == 0, "rotlie binary " << args << ": " << r.err);
  return nlohmann::json::parse(r.out);
}

double distance(const nlohmann::json& a, const nlohmann::json& b) {
  double d = 0;
  for (const char* key : {"r", "v"})
    for (std::size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(a[key][k].get<double>() - b[key][k].get<double>()) * (key[0] == 'v' ? 1e4 : 1.0));
  for (const char* key : {"Q1", "Q2"})
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t k = 0; k < 3; ++k) d = std::max(d, std::abs(a[key][i][k].get<double>() - b[key][i][k].get<double>()));
  return d;
}

const std::string didymos = "--system didymos --order 2";

}  // namespace

BOOST_AUTO_TEST_CASE(the_json_has_the_contracts_fields_and_the_start_at_T_0) {
  const auto j = binary_json("--primary ellipsoid:0.4,0.38,0.35 --secondary ellipsoid:0.1,0.08,0.06 --density 2000,2500 --separation 1.3 "
                             "--primary-period 2.5 --integrator SIER2 --T 0");
  for (const char* key : {"masses", "moments", "t", "r", "v", "Q1", "Q2", "omega1", "omega2", "energy", "angular_momentum", "max_rel_energy_error",
                          "max_rel_angular_momentum_error", "cpu_s", "mutual"})
    BOOST_TEST(j.contains(key), key);
  for (const char* key : {"U", "F", "M1", "M2"}) BOOST_TEST(j["mutual"].contains(key), key);
  const double pi = std::acos(-1.0), G = 6.67430e-20;
  const double M1 = 2000 * 1e9 * 4 * pi / 3 * 0.4 * 0.38 * 0.35, M2 = 2500 * 1e9 * 4 * pi / 3 * 0.1 * 0.08 * 0.06;
  BOOST_TEST(j["masses"][0].get<double>() == M1, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(j["masses"][1].get<double>() == M2, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(j["moments"][0][2].get<double>() == M1 * (0.4 * 0.4 + 0.38 * 0.38) / 5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(j["t"].get<double>() == 0.0);
  BOOST_TEST(j["r"][0].get<double>() == 1.3);
  BOOST_TEST(j["Q1"][0][0].get<double>() == 1.0);
  BOOST_TEST(j["omega1"][2].get<double>() == 2 * pi / (2.5 * 3600), boost::test_tools::tolerance(1e-14));
  // the circular rate balances the pull: μ n² R = −F_x, and the secondary turns with it
  const double mu = M1 * M2 / (M1 + M2), n = j["v"][1].get<double>() / 1.3;
  BOOST_TEST(mu * n * n * 1.3 == -j["mutual"]["F"][0].get<double>(), boost::test_tools::tolerance(1e-13));
  BOOST_TEST(j["omega2"][2].get<double>() == n, boost::test_tools::tolerance(1e-13));
  // MacCullagh: U = −G M1 M2 / R (1 + the bodies' second-degree terms, here a few per cent)
  const double U0 = -G * M1 * M2 / 1.3;
  BOOST_TEST(j["mutual"]["U"].get<double>() < U0);
  BOOST_TEST(j["mutual"]["U"].get<double>() > 1.05 * U0);
  // aligned frames on the x axis: no torque
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(std::abs(j["mutual"]["M2"][k].get<double>()) <= 1e-20 * std::abs(U0));
}

BOOST_AUTO_TEST_CASE(every_integrator_family_agrees_with_rkf78_on_didymos) {
  // five mutual orbits (11.9 h each) of the Didymos system at order 2
  const std::string T = "214200";
  const auto reference = binary_json(didymos + " --integrator odeint-rkf78:1e-13 --h 600 --T " + T);
  for (const auto& [name, h, tolerance] : {std::tuple{"SIER2", "10", 2e-3}, std::tuple{"SIER4", "60", 1e-5}, std::tuple{"KEPLER2", "30", 1e-3},
                                           std::tuple{"KEPLER4", "120", 1e-5}, std::tuple{"SIER4/ABCBA2:ABC", "60", 1e-2}, std::tuple{"RK4", "20", 1e-5},
                                           std::tuple{"LGVI", "10", 2e-3}, std::tuple{"odeint-dopri5:1e-11", "600", 1e-5}}) {
    const auto j = binary_json(didymos + " --integrator " + name + " --h " + h + " --T " + T);
    const double d = distance(j, reference);
    BOOST_TEST_MESSAGE(name << " at h = " << h << " s: distance from RKF78 " << d << ", energy error " << j["max_rel_energy_error"] << ", angular momentum "
                            << j["max_rel_angular_momentum_error"] << ", " << j["cpu_s"] << " s");
    BOOST_TEST(d < tolerance, name);
    BOOST_TEST(j["unstable"] == false, name);
    const std::string n = name;
    if (n != "RK4" && n.rfind("odeint", 0) != 0) BOOST_TEST(j["max_rel_angular_momentum_error"].get<double>() < 1e-13, name);
  }
}

// Orders 2 to 8 on Didymos (issue 45): the mutual potential's successive corrections shrink as (size/r)²
// (0.4 km against 1.2 km: about 1/9 per two degrees), and an order-8 run keeps the total angular momentum
// to round-off and lies closer to order 6 than order 6 to order 4.
BOOST_AUTO_TEST_CASE(higher_orders_converge_on_didymos) {
  std::vector<double> U;
  for (const int order : {2, 4, 6, 8}) U.push_back(binary_json("--system didymos --order " + std::to_string(order) + " --integrator SIER4 --T 0")["mutual"]["U"]);
  for (std::size_t k = 2; k < U.size(); ++k) {
    const double ratio = std::abs(U[k - 1] - U[k - 2]) / std::abs(U[k] - U[k - 1]);
    BOOST_TEST_MESSAGE("orders " << 2 * k << " to " << 2 * k + 2 << ": U changes by " << std::abs(U[k] - U[k - 1]) / std::abs(U[k]) << ", "
                                 << ratio << "x less than the step before");
    BOOST_TEST(ratio > 5);
  }
  const std::string run_args = " --integrator SIER4 --h 60 --T 7200 --no-error-estimate";
  const auto four = binary_json("--system didymos --order 4" + run_args), six = binary_json("--system didymos --order 6" + run_args),
             eight = binary_json("--system didymos --order 8" + run_args);
  BOOST_TEST(eight["max_rel_angular_momentum_error"].get<double>() < 1e-13);
  BOOST_TEST(eight["order"] == 8);
  BOOST_TEST(distance(eight, six) < distance(six, four));
}

BOOST_AUTO_TEST_CASE(a_run_continues_from_its_own_output) {
  const auto whole = binary_json(didymos + " --integrator SIER4 --h 60 --T 7200");
  const auto half = binary_json(didymos + " --integrator SIER4 --h 60 --T 3600");
  const auto path = fs::temp_directory_path() / ("rotlie-binary-state-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << half.dump();
  const auto rest = binary_json(didymos + " --integrator SIER4 --h 60 --T 3600 --state " + path.string());
  fs::remove(path);
  BOOST_TEST(distance(rest, whole) < 1e-12);
}

BOOST_AUTO_TEST_CASE(the_trajectory_lines_start_at_the_start) {
  const auto r = run("binary " + didymos + " --integrator KEPLER2 --h 60 --T 600 --every 5 --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  std::istringstream lines(r.out);
  std::string line;
  std::vector<nlohmann::json> rows;
  while (std::getline(lines, line)) rows.push_back(nlohmann::json::parse(line));
  BOOST_TEST_REQUIRE(rows.size() == 4u);  // t = 0, 300, 600, then the run's JSON
  BOOST_TEST(rows[0]["t"].get<double>() == 0.0);
  BOOST_TEST(rows[2]["t"].get<double>() == 600.0);
  BOOST_TEST(rows[3]["t"].get<double>() == 600.0);
  BOOST_TEST(distance(rows[2], rows[3]) == 0.0);
}

BOOST_AUTO_TEST_CASE(bodies_that_touch_stop_the_run_and_say_when) {
  // a secondary ball grazing the primary's equator (pericentre 0.3 km, inside the primary's
  // cross-section of radius b = 0.3 km plus the ball's 0.05 km): contact before the pericentre
  const auto path = fs::temp_directory_path() / ("rotlie-binary-graze-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"({"r": [1.0, 0, 0], "v": [0, 7.9e-5, 0], "Q1": [[1,0,0],[0,1,0],[0,0,1]], "Q2": [[1,0,0],[0,1,0],[0,0,1]],
                          "omega1": [0, 0, 0], "omega2": [0, 0, 0]})";
  const auto r = run("binary --primary ellipsoid:0.4,0.3,0.2 --secondary ellipsoid:0.05,0.05,0.05 --density 2000 --integrator SIER2 --h 10 --T 20000 --state " +
                     path.string());
  fs::remove(path);
  BOOST_TEST(r.status == 1, r.err);
  BOOST_TEST(r.err.find("the bodies touch at t = ") != std::string::npos, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

// Issue 43: values that look like unit mistakes are refused in one line naming the likely unit (exit 2),
// and run as given with --force.
BOOST_AUTO_TEST_CASE(unit_mistakes_are_refused_naming_the_likely_unit) {
  const std::pair<std::string, std::string> cases[] = {
      {"--system didymos --G 6.674e-11", "SI's value in m3 kg-1 s-2"},
      {"--system didymos --density 2.1", "a density in g/cm3?"},
      {"--primary ellipsoid:400,390,350 --secondary ellipsoid:90,80,70 --density 2000 --separation 1.2", "sizes in metres?"},
      {"--system didymos --primary-period 0.005", "periods are in hours"}};
  for (const auto& [args, unit] : cases) {
    const auto r = run("binary " + args + " --integrator SIER4 --h 60 --T 600");
    BOOST_TEST(r.status == 2, args << ": " << r.err);
    BOOST_TEST(r.err.find(unit) != std::string::npos, r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  }
  const auto forced = binary_json("--system didymos --density 2.1 --force --integrator SIER4 --h 60 --T 600");
  BOOST_TEST(forced["densities"][0].get<double>() == 2.1);
}

// The Sun (issue 43's contract): its values join the JSON; at M0 = 0 the barycentre is at perihelion,
// so |S| = a (1 − e) AU.
BOOST_AUTO_TEST_CASE(the_sun_joins_the_json) {
  const auto j = binary_json(didymos + " --integrator KEPLER4 --h 600 --T 0 --sun 1.64,0.38,3.4,73.2,319.3,0");
  BOOST_TEST_REQUIRE(j.contains("sun"));
  double S = 0;
  for (std::size_t k = 0; k < 3; ++k) S += std::pow(j["sun"]["position"][k].get<double>(), 2);
  BOOST_TEST(std::abs(std::sqrt(S) / (1.64 * 0.62 * 149597870.7) - 1) < 1e-14);
  for (const char* key : {"acceleration", "M1", "M2"}) BOOST_TEST(j["sun"][key].size() == 3u);
  const auto r = run("binary " + didymos + " --integrator SIER4 --h 60 --T 600 --sun 1,1.5,0,0,0,0");
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(r.err.find("--sun: the eccentricity must be in [0, 1)") != std::string::npos, r.err);
}

// --observe and --impulse (issue 43): at order 0 the mutual orbit is Kepler's circle, so the mean and
// osculating periods are 2π √(R³/GM) and e = 0; a vector impulse on the secondary adds to v exactly,
// on the primary subtracts; DART's form opposes the secondary's motion with β m U / M₂.
BOOST_AUTO_TEST_CASE(observables_and_impulses) {
  const auto j = binary_json("--primary ellipsoid:0.4,0.38,0.35 --secondary ellipsoid:0.1,0.08,0.06 --density 2000 --separation 1.2 --order 0 "
                             "--integrator KEPLER4 --h 600 --T 172800 --observe");
  const double GM = 6.67430e-20 * (j["masses"][0].get<double>() + j["masses"][1].get<double>());
  const double kepler_h = 2 * std::acos(-1.0) * std::sqrt(1.2 * 1.2 * 1.2 / GM) / 3600;
  const auto& o = j["observables"];
  BOOST_TEST(std::abs(o["osculating"]["period_h"].get<double>() / kepler_h - 1) < 1e-12);
  BOOST_TEST(std::abs(o["orbit_period_h"].get<double>() / kepler_h - 1) < 1e-9);
  BOOST_TEST(o["osculating"]["e"].get<double>() < 1e-12);
  BOOST_TEST(std::abs(o["spin_periods_h"][1].get<double>() / kepler_h - 1) < 1e-12);  // synchronous, and order 0 exerts no torque
  const auto at_rest = binary_json(didymos + " --integrator SIER4 --T 0");
  const auto pushed = binary_json(didymos + " --integrator SIER4 --T 0 --impulse secondary:1,-2.5,0.5");
  const auto pulled = binary_json(didymos + " --integrator SIER4 --T 0 --impulse primary:1,-2.5,0.5");
  const double dv[3] = {1e-6, -2.5e-6, 0.5e-6};
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(pushed["v"][k].get<double>() == at_rest["v"][k].get<double>() + dv[k]);
    BOOST_TEST(pulled["v"][k].get<double>() == at_rest["v"][k].get<double>() - dv[k]);
  }
  const auto dart = binary_json(didymos + " --integrator SIER4 --T 0 --impulse secondary:beta=3.61,m=579.4,U=6.1448");
  const double size = 3.61 * 579.4 * 6.1448 / at_rest["masses"][1].get<double>();
  const double v0 = at_rest["v"][1].get<double>();  // the circular start moves along +y
  BOOST_TEST(std::abs(dart["v"][1].get<double>() - (v0 - size)) < 1e-18);
  BOOST_TEST(run("binary " + didymos + " --integrator SIER4 --T 0 --impulse moon:1,2,3").status == 2);
}

// Issue 46: numbers in a --state file or a shape file that a double cannot hold, or that the run's
// energies and integrals would overflow with, are refused in one line naming the file and the field
// or line (exit 2), and a message about an attitude shows finite, true numbers.
namespace {

struct scratch_file {
  fs::path path;
  scratch_file(const std::string& name, const std::string& text)
      : path(fs::temp_directory_path() / ("rotlie-binary-" + std::to_string(::getpid()) + "-" + name)) {
    std::ofstream(path) << text;
  }
  ~scratch_file() { fs::remove(path); }
};

void check_refusal(const std::string& args, const std::string& file, const std::string& words) {
  const auto r = run("binary " + args);
  BOOST_TEST(r.status == 2, args << ": " << r.err);
  BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  BOOST_TEST(r.err.find(file) != std::string::npos, r.err);
  BOOST_TEST(r.err.find(words) != std::string::npos, "'" << r.err << "' should say '" << words << "'");
  BOOST_TEST((r.err.find("inf") == std::string::npos && r.err.find("nan") == std::string::npos), r.err);
}

// An OBJ file of these boxes [x, x + s]³ (counter-clockwise from outside), each vertex written once.
std::string boxes_obj(const std::vector<std::array<double, 3>>& corners, double s) {
  std::vector<std::array<double, 3>> vertices;
  std::string facets;
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& c : corners) {
    int index[8];
    for (int i = 0; i < 8; ++i) {
      const std::array<double, 3> v{c[0] + (i & 1 ? s : 0), c[1] + (i & 2 ? s : 0), c[2] + (i & 4 ? s : 0)};
      const auto found = std::find(vertices.begin(), vertices.end(), v);
      index[i] = static_cast<int>(found - vertices.begin()) + 1;
      if (found == vertices.end()) vertices.push_back(v);
    }
    for (const auto& f : faces)
      for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}})
        facets += "f " + std::to_string(index[t[0]]) + " " + std::to_string(index[t[1]]) + " " + std::to_string(index[t[2]]) + "\n";
  }
  std::ostringstream out;
  out.precision(17);
  for (const auto& v : vertices) out << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
  return out.str() + facets;
}

}  // namespace

BOOST_AUTO_TEST_CASE(out_of_range_numbers_in_a_state_file_are_named) {
  const auto start = binary_json(didymos + " --integrator SIER2 --h 60 --T 0");
  nlohmann::json state;
  for (const char* key : {"r", "v", "Q1", "Q2", "omega1", "omega2"}) state[key] = start[key];
  const auto with = [&](const char* key, const nlohmann::json& value) {
    auto s = state;
    s[key] = value;
    return s.dump();
  };
  const nlohmann::json identity = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  auto reflection = identity, huge = identity, beyond = identity;
  reflection[0][0] = -1, huge[0][0] = 1e300, beyond[0][0] = 1e200;
  // 1e999 is no double: written into the text, the parser refuses it
  auto text_999 = with("r", {7777, 0, 0});
  text_999.replace(text_999.find("7777"), 4, "1e999");
  auto text_minus_999 = with("Q2", {{1, 0, 0}, {0, 7777, 0}, {0, 0, 1}});
  text_minus_999.replace(text_minus_999.find("7777"), 4, "-1e999");
  const std::pair<std::string, std::string> cases[] = {
      {with("r", {1e308, 0, 0}), "\"r\"[0] = 1e+308 is out of range"},
      {with("v", {0, 1e308, 0}), "\"v\"[1] = 1e+308 is out of range"},
      {with("omega1", {1e300, 0, 0}), "\"omega1\"[0] = 1e+300 is out of range"},
      {with("Q1", huge), "\"Q1\" is not a rotation (its entry [0][0] = 1e+300 lies outside [-1, 1])"},
      {with("Q1", beyond), "\"Q1\" is not a rotation (its entry [0][0] = 1e+200 lies outside [-1, 1])"},
      {with("Q1", reflection), "\"Q1\" is not a rotation (|QᵀQ − 1| = 0, det -1: a reflection)"},
      {with("Q1", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}), "\"Q1\" is not a rotation (|QᵀQ − 1| = 1, det 0)"},
      {with("r", {1e-200, 0, 0}), "\"r\" is out of range (|r| = 1e-200 km"},
      {text_999, "\"r\"[0] = 1e999 is out of range"},
      {text_minus_999, "\"Q2\"[1][1] = -1e999 is out of range"},
  };
  for (const auto& [text, words] : cases) {
    const scratch_file file("state.json", text);
    check_refusal(didymos + " --integrator SIER2 --h 10 --T 100 --state " + file.path.string(), file.path.filename().string(), words);
  }
}

BOOST_AUTO_TEST_CASE(out_of_range_numbers_in_a_shape_file_are_named) {
  const std::string facets = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::pair<std::string, std::string> cases[] = {
      {"v 0 0 0\nv 1e200 0 0\nv 0 0.2 0\nv 0 0 0.2\n" + facets, "line 2: vertex coordinate 1e200 is out of range"},
      {"v 0 0 0\nv 0.2 0 0\nv 0 1e400 0\nv 0 0 0.2\n" + facets, "line 3: vertex coordinate 1e400 is out of range"},
      {"v 0 0 0\nv 2e-200 0 0\nv 0 2e-200 0\nv 0 0 2e-200\n" + facets, "the vertices span 2e-200 km, out of range"},
      {"4 4\n0 0 0\n0.2 0 0\n0 0.2 0\n0 0 -1e400\n1 3 2\n1 2 4\n1 4 3\n2 3 4\n", "line 5: vertex coordinate -1e400 is out of range"},
  };
  for (const auto& [text, words] : cases) {
    const scratch_file file("shape.obj", text);
    check_refusal("--primary polyhedron:" + file.path.string() + " --secondary ellipsoid:0.1,0.08,0.06 --density 2000 --separation 1.2 --integrator SIER2 --T 0",
                  file.path.filename().string(), words);
  }
}

// Two cubes of side s = 0.2 km sharing an edge are one solid: mass 2ρs³, principal moments ρs⁵ (1/3,
// 4/3, 4/3) (the closed form of polyhedron_check_test); two overlapping cubes are refused.
BOOST_AUTO_TEST_CASE(a_solid_with_an_edge_of_four_facets_runs_and_a_surface_crossing_itself_does_not) {
  const double s = 0.2, rho = 2000 * 1e9;
  const scratch_file cubes("cubes.obj", boxes_obj({{0, 0, 0}, {s, s, 0}}, s));
  const auto j = binary_json("--primary polyhedron:" + cubes.path.string() +
                             " --secondary ellipsoid:0.1,0.08,0.06 --density 2000 --separation 1.2 --integrator SIER2 --T 0");
  BOOST_TEST(j["masses"][0].get<double>() == 2 * rho * s * s * s, boost::test_tools::tolerance(1e-13));
  const double moments[3] = {1.0 / 3, 4.0 / 3, 4.0 / 3};
  for (std::size_t k = 0; k < 3; ++k)
    BOOST_TEST(j["moments"][0][k].get<double>() == moments[k] * rho * std::pow(s, 5), boost::test_tools::tolerance(1e-12));
  const scratch_file crossing("crossing.obj", boxes_obj({{0, 0, 0}, {s / 2, s / 2, s / 2}}, s));
  check_refusal("--primary polyhedron:" + crossing.path.string() + " --secondary ellipsoid:0.1,0.08,0.06 --density 2000 --separation 1.2 --integrator SIER2 --T 0",
                crossing.path.filename().string(), "the surface meets itself: facets");
}

BOOST_AUTO_TEST_SUITE_END()  // binary_cli_test
