// GUBAS's configuration file as a `rotlie binary` request (gubas_config.hpp). The configurations are
// written here with the keys and values of GUBAS's own examples (fork meyeralexj/gubas: at commit
// 8db57ff4f918a75b8391afae1a4e86a3b2e1ebff, example/hou_config.cfg, the Didymos system; at commit
// f8154389f8a93318e63edc2ba7d4103179bac6b3, hou_config.cfg, a KW4-like pair), their comments left
// out; their shape files are replaced by boxes of our own in GUBAS's CSV form. The mapped setup is
// checked against values computed here from the SI numbers, and each refusal is one line naming the option.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <unistd.h>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/gubas_config.hpp"
#include "rotlie/runs/user_input.hpp"

BOOST_AUTO_TEST_SUITE(gubas_config_test)

using namespace rotlie;
namespace fs = std::filesystem;
using models::mat3;
using models::vec3;

namespace {

using options = std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>>;

// example/hou_config.cfg at 8db57ff4: the sections, keys and values in the file's order.
options didymos_example() {
  return {{"Gravity Parameter", {{"G", "6.67e-11"}}},
          {"Initial Conditions",
           {{"Fahnestock Input File Flag", "0"}, {"Relative Position X", "1200.0"}, {"Relative Position Y", "0."}, {"Relative Position Z", "0."},
            {"Relative Velocity X", "0."}, {"Relative Velocity Y", "0.175704287113523"}, {"Relative Velocity Z", "0."},
            {"Primary Angular Velocity X", "0.0"}, {"Primary Angular Velocity Y", "0.0"}, {"Primary Angular Velocity Z", "0.000772269580528"},
            {"Secondary Angular Velocity X", "0.0"}, {"Secondary Angular Velocity Y", "0.0"}, {"Secondary Angular Velocity Z", "0.000146420239261"},
            {"B into A (1,1)", "1.0"}, {"B into A (1,2)", "0.0"}, {"B into A (1,3)", "0.0"}, {"B into A (2,1)", "0.0"}, {"B into A (2,2)", "1.0"},
            {"B into A (2,3)", "0.0"}, {"B into A (3,1)", "0.0"}, {"B into A (3,2)", "0.0"}, {"B into A (3,3)", "1.0"}, {"B into A Euler Flag", "1"},
            {"B into A Euler 1 X", "0."}, {"B into A Euler 2 Y", "0."}, {"B into A Euler 3 Z", "0."},
            {"A into N (1,1)", "1.0"}, {"A into N (1,2)", "0.0"}, {"A into N (1,3)", "0.0"}, {"A into N (2,1)", "0.0"}, {"A into N (2,2)", "1.0"},
            {"A into N (2,3)", "0.0"}, {"A into N (3,1)", "0.0"}, {"A into N (3,2)", "0.0"}, {"A into N (3,3)", "1.0"}, {"A into N Euler Flag", "1"},
            {"A into N Euler 1 X", "0."}, {"A into N Euler 2 Y", "0."}, {"A into N Euler 3 Z", "0."}}},
          {"Integration Settings", {{"Start Time", "0.0"}, {"Final Time", "7200."}, {"Integrator Flag", "2"}, {"Fixed Time Step", "30."}, {"Absolute Tolerance", "1.e-15"}}},
          {"Output Settings", {{"Post Processing", "1"}, {"Fixed Output Frequency", "3600."}, {"Specified Time List Filename", "filler.csv"}, {"Case Name", "Test"}}},
          {"Body Model Definitions",
           {{"Inertia Integral Generation Flag", "1"}, {"Primary Shape Flag", "2"}, {"Secondary Shape Flag", "1"},
            {"Primary Semi-Major Axis", "576.7195"}, {"Primary Semi-Intermediate Axis", "576.7195"}, {"Primary Semi-Minor Axis", "576.7195"},
            {"Secondary Semi-Major Axis", "103.16"}, {"Secondary Semi-Intermediate Axis", "79.35"}, {"Secondary Semi-Minor Axis", "66.13"},
            {"Primary Vertex File", "Didymos_A_vert_met.csv"}, {"Primary Tetrahedron File", "Didymos_A_facet.csv"},
            {"Secondary Vertex File", "Didymos_B_vert_met.csv"}, {"Secondary Tetrahedron File", "Didymos_B_facet.csv"},
            {"Primary Density", "2.203111036687207"}, {"Secondary Density", "2.203111036687207"}}},
          {"Mutual Gravity Expansion Parameters",
           {{"Gravity Expansion Truncation Order", "4"}, {"Primary Inertia Integral Truncation Order", "4"}, {"Secondary Inertia Integral Truncation Order", "4"}}},
          {"Additional Forces and Perturbations",
           {{"Flyby", "0"}, {"Planetary Mass", "5.9722e24"}, {"Semimajor Axis", "-1.1072e+04"}, {"Eccentricity", "9.1284"}, {"Inclination", "0.1745"},
            {"RAAN", "0.1745"}, {"Argument of Periapsis", "0.1745"}, {"Flyby Time", "345600.0"}, {"Heliocentric Orbit", "0"}, {"Sun Mass", "1.989e+30"},
            {"Heliocentric Semimajor Axis", "246013901.32"}, {"Heliocentric Eccentricity", "0.38362664"}, {"Heliocentric Inclination", "0.059475759"},
            {"Heliocentric RAAN", "1.277649080300677"}, {"Heliocentric Argument of Periapsis", "5.5732150380"}, {"Time of periapsis passage", "2582993.15688"},
            {"Solar Gravity", "0"}, {"Solar Orbit Radius", "1."}, {"AU Definition", "149597870700."}, {"Solar Mass", "1.988e30"}, {"Tidal Torque", "0"},
            {"Primary Love Number", "1.e-5"}, {"Secondary Love Number", "1.e-5"}, {"Primary Reference Radius", "660."}, {"Secondary Reference Radius", "225."},
            {"Primary Tidal Lag Angle", ".005"}, {"Secondary Tidal Lag Angle", ".005"}}}};
}

// hou_config.cfg at f8154389: the same file before the flyby and heliocentric options, differing in these values.
options kw4_example() {
  auto o = didymos_example();
  const std::map<std::string, std::string> changed = {
      {"Relative Position X", "1800.0"}, {"Relative Velocity Y", "0.0"}, {"Primary Angular Velocity Z", "1.e-5"}, {"Secondary Angular Velocity Z", "0.0"},
      {"Final Time", "86400."}, {"Integrator Flag", "1"}, {"Fixed Time Step", "5."}, {"Fixed Output Frequency", "40."}, {"Case Name", "output_example"},
      {"Secondary Shape Flag", "2"}, {"Primary Semi-Major Axis", "398.88"}, {"Primary Semi-Intermediate Axis", "391.30"}, {"Primary Semi-Minor Axis", "383.48"},
      {"Secondary Semi-Major Axis", "103.83"}, {"Secondary Semi-Intermediate Axis", "79.73"}, {"Secondary Semi-Minor Axis", "66.95"},
      {"Primary Vertex File", "kw4a_p_fixm.csv"}, {"Primary Tetrahedron File", "kw4a_tri.csv"}, {"Secondary Vertex File", "kw4b_p_fixm.csv"},
      {"Secondary Tetrahedron File", "kw4b_tri.csv"}, {"Primary Density", "1.97"}, {"Secondary Density", "2.81"}, {"Solar Gravity", "1"}, {"Tidal Torque", "1"}};
  for (auto& [section, keys] : o) {
    std::erase_if(keys, [](const auto& kv) { return kv.first == "Post Processing"; });
    if (section == "Additional Forces and Perturbations")
      keys = {{"Solar Gravity", "1"}, {"Solar Orbit Radius", "1."}, {"AU Definition", "149597870700."}, {"Solar Mass", "1.988e30"}, {"Tidal Torque", "1"},
              {"Primary Love Number", "1.e-5"}, {"Secondary Love Number", "1.e-5"}, {"Primary Reference Radius", "660."},
              {"Secondary Reference Radius", "225."}, {"Primary Tidal Lag Angle", ".005"}, {"Secondary Tidal Lag Angle", ".005"}};
    for (auto& [key, value] : keys)
      if (changed.count(key)) value = changed.at(key);
  }
  return o;
}

void set(options& o, const std::string& key, const std::string& value) {
  for (auto& [section, keys] : o)
    for (auto& [k, v] : keys)
      if (k == key) {
        v = value;
        return;
      }
  BOOST_FAIL("no option " << key);
}

std::string text_of(const options& o, const std::string& left_out = "") {
  std::string t = "# written by the test\n";
  for (const auto& [section, keys] : o) {
    t += "##########\n[" + section + "]\n";
    for (const auto& [k, v] : keys)
      if (k != left_out) t += k + ": " + v + "\n";
  }
  return t;
}

const fs::path& folder() {
  static const fs::path dir = [] {
    const auto d = fs::temp_directory_path() / ("rotlie-gubas-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// A box of half-sides (m) turned by R in its file's frame, as GUBAS's CSV pair: "0,x,y,z" rows and 1-based
// facet rows ending ",,", turned inward (GUBAS takes |det|, so its files may face either way).
void write_box(const std::string& vertices, const std::string& facets, double a, double b, double c, const mat3<double>& R) {
  std::ofstream v(folder() / vertices), f(folder() / facets);
  v.precision(17);
  for (int i = 0; i < 8; ++i) {
    const auto p = R * vec3<double>{i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c};
    v << "0," << p[0] << "," << p[1] << "," << p[2] << "\n";
  }
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};  // outward, counter-clockwise
  for (const auto& q : faces) f << q[0] + 1 << "," << q[2] + 1 << "," << q[1] + 1 << ",,\n" << q[0] + 1 << "," << q[3] + 1 << "," << q[2] + 1 << ",,\n";
}

runs::gubas_mapping mapped(const options& o, const std::string& left_out = "") {
  return runs::parse_gubas_config(text_of(o, left_out), folder(), "--gubas-config hou_config.cfg");
}

std::string refusal(const options& o, const std::string& left_out = "") {
  try {
    runs::binary_setup_of(mapped(o, left_out).request);
  } catch (const runs::bad_input& e) {
    BOOST_TEST(std::string(e.what()).find('\n') == std::string::npos);
    return e.what();
  }
  return "";
}

mat3<double> turn(int axis, double angle) {  // the active rotation about a coordinate axis
  mat3<double> R = mat3<double>::identity();
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  R(i, i) = R(j, j) = std::cos(angle), R(j, i) = std::sin(angle), R(i, j) = -std::sin(angle);
  return R;
}

bool near(double x, double y, double tolerance) { return std::abs(x - y) <= tolerance * std::max(1.0, std::abs(y)); }

const double pi = std::numbers::pi;

}  // namespace

// Didymos: the primary a box of ours turned in its file (its principal frame is not the file's),
// the secondary GUBAS's ellipsoid; the LGVI at 30 s over 7200 s at order 4.
BOOST_AUTO_TEST_CASE(the_didymos_example_maps_to_rotlies_units) {
  const auto R = turn(2, 0.3) * turn(0, 0.2);
  write_box("Didymos_A_vert_met.csv", "Didymos_A_facet.csv", 320, 315, 310, R);
  const auto m = mapped(didymos_example());
  BOOST_TEST(m.request.integrator == "LGVI");
  const auto s = runs::binary_setup_of(m.request);
  const double rho = 2.203111036687207e12;  // kg/km³
  const double M1 = rho * 8 * 0.32 * 0.315 * 0.31, M2 = rho * 4 * pi / 3 * 0.10316 * 0.07935 * 0.06613;
  const auto sys = s.system_model();
  BOOST_TEST(near(sys.body(0).mass, M1, 1e-13));
  BOOST_TEST(near(sys.body(1).mass, M2, 1e-13));
  const double I1[3] = {M1 * (0.315 * 0.315 + 0.31 * 0.31) / 3, M1 * (0.32 * 0.32 + 0.31 * 0.31) / 3, M1 * (0.32 * 0.32 + 0.315 * 0.315) / 3};
  const double I2[3] = {M2 * (0.07935 * 0.07935 + 0.06613 * 0.06613) / 5, M2 * (0.10316 * 0.10316 + 0.06613 * 0.06613) / 5,
                        M2 * (0.10316 * 0.10316 + 0.07935 * 0.07935) / 5};
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(near(sys.moments(0)[k], I1[k], 1e-12), "primary " << k);
    BOOST_TEST(near(sys.moments(1)[k], I2[k], 1e-13), "secondary " << k);
  }
  BOOST_TEST(near(s.G, 6.67e-20, 1e-15));
  BOOST_TEST(s.order == 4);
  BOOST_TEST(s.h == 30.0);
  BOOST_TEST(s.T == 7200.0);
  BOOST_TEST(s.steps == 240);
  // the start: km and km/s, frames A = N; the primary's principal axes are R's columns up to sign
  const vec3<double> r{1.2, 0, 0}, v{0, 0.175704287113523e-3, 0};
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(near(s.start.r[k], r[k], 1e-15));
    BOOST_TEST(near(s.start.v[k], v[k], 1e-15));
  }
  const auto Q1 = s.start.body[0].Q, Q2 = s.start.body[1].Q;
  for (int k = 0; k < 3; ++k) BOOST_TEST(std::abs(std::abs(Q1(0, k) * R(0, k) + Q1(1, k) * R(1, k) + Q1(2, k) * R(2, k)) - 1) < 1e-12, "axis " << k);
  // each spin, turned into the inertial frame, is GUBAS's (the frames start aligned)
  const auto w1 = Q1 * models::angular_velocity(sys.moments(0), s.start.body[0].G), w2 = Q2 * models::angular_velocity(sys.moments(1), s.start.body[1].G);
  const vec3<double> spin1{0, 0, 0.000772269580528}, spin2{0, 0, 0.000146420239261};
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(std::abs(w1[k] - spin1[k]) < 1e-17, "primary " << k);
    BOOST_TEST(std::abs(w2[k] - spin2[k]) < 1e-17, "secondary " << k);
    for (std::size_t j = 0; j < 3; ++j) BOOST_TEST(Q2(static_cast<int>(j), static_cast<int>(k)) == (j == k ? 1.0 : 0.0));
  }
  BOOST_TEST(s.primary.density == 2203.111036687207, s.primary.density);  // kg/m³, from the decimal
}

// The Euler angles as GUBAS's driver reads them (rotations about x, y, z in turn), and A into N turning r and v.
BOOST_AUTO_TEST_CASE(attitudes_turn_the_start_as_gubas_does) {
  write_box("Didymos_A_vert_met.csv", "Didymos_A_facet.csv", 320, 315, 310, mat3<double>::identity());
  auto o = didymos_example();
  set(o, "B into A Euler 1 X", "0.1"), set(o, "B into A Euler 2 Y", "0.2"), set(o, "B into A Euler 3 Z", "0.3");
  set(o, "A into N Euler Flag", "0");
  const auto C_AN = turn(2, 0.5);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::ostringstream entry;
      entry.precision(17);
      entry << C_AN(i, j);
      set(o, "A into N (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")", entry.str());
    }
  const auto state = nlohmann::json::parse(mapped(o).request.state_text);
  const auto C_BA = turn(0, 0.1) * turn(1, 0.2) * turn(2, 0.3);
  const auto Q2 = C_AN * C_BA;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) BOOST_TEST(std::abs(state["Q2"][i][j].get<double>() - Q2(static_cast<int>(i), static_cast<int>(j))) < 1e-15);
  // r = C_AN (1.2, 0, 0) km, v = C_AN (0, 0.1757…, 0) m/s in km/s
  BOOST_TEST(std::abs(state["r"][0].get<double>() - 1.2 * std::cos(0.5)) < 1e-15);
  BOOST_TEST(std::abs(state["r"][1].get<double>() - 1.2 * std::sin(0.5)) < 1e-15);
  BOOST_TEST(std::abs(state["v"][0].get<double>() + 0.175704287113523e-3 * std::sin(0.5)) < 1e-18);
}

// The KW4 example maps but for its solar gravity and tides, which rotlie does not model as GUBAS does.
BOOST_AUTO_TEST_CASE(the_kw4_example_is_refused_for_its_perturbations_and_maps_without_them) {
  write_box("kw4a_p_fixm.csv", "kw4a_tri.csv", 400, 390, 380, mat3<double>::identity());
  write_box("kw4b_p_fixm.csv", "kw4b_tri.csv", 100, 80, 70, turn(1, 0.4));
  auto o = kw4_example();
  BOOST_TEST(refusal(o).find("GUBAS option 'Solar Gravity' (Hill's solar tide on a circular orbit) has no rotlie counterpart") != std::string::npos, refusal(o));
  set(o, "Solar Gravity", "0");
  BOOST_TEST(refusal(o).find("GUBAS option 'Tidal Torque'") != std::string::npos, refusal(o));
  set(o, "Tidal Torque", "0");
  const auto m = mapped(o);
  BOOST_TEST(m.request.integrator == "RK4");
  BOOST_TEST(m.request.h == "5");
  BOOST_TEST(m.request.T == "86400");
  BOOST_TEST(m.request.density == "1970,2810");
  BOOST_TEST(m.request.order == "4");
  const auto state = nlohmann::json::parse(m.request.state_text);
  BOOST_TEST(state["r"][0].get<double>() == 1.8);
  BOOST_TEST(state["v"][1].get<double>() == 0.0);
  // at rest 1.8 km apart the pair falls straight together: rotlie refuses the start as colliding
  BOOST_TEST(refusal(o).find("pericentre") != std::string::npos, refusal(o));
}

BOOST_AUTO_TEST_CASE(what_rotlie_cannot_run_as_gubas_would_is_refused_by_name) {
  write_box("Didymos_A_vert_met.csv", "Didymos_A_facet.csv", 320, 315, 310, mat3<double>::identity());
  const auto refused = [](const std::string& key, const std::string& value, const std::string& part) {
    auto o = didymos_example();
    set(o, key, value);
    const auto why = refusal(o);
    BOOST_TEST(why.find(part) != std::string::npos, key << " = " << value << ": '" << why << "' lacks '" << part << "'");
  };
  refused("Integrator Flag", "4", "'Integrator Flag' = 4 (the Adams-Bashforth-Moulton predictor-corrector) has no rotlie counterpart");
  refused("Integrator Flag", "7", "'Integrator Flag' = 7 is none of GUBAS's integrators");
  refused("Fahnestock Input File Flag", "1", "'Fahnestock Input File Flag' (the start, G and densities from Fahnestock's files) has no rotlie counterpart");
  refused("Flyby", "1", "'Flyby' (a planet's flyby");
  refused("Heliocentric Orbit", "1", "'Heliocentric Orbit' (the Sun");
  refused("Start Time", "100", "'Start Time' (the clock at the start, 100 s) has no rotlie counterpart");
  refused("Gravity Expansion Truncation Order", "2", "'Gravity Expansion Truncation Order' (2) differs");
  refused("Secondary Inertia Integral Truncation Order", "2", "'Secondary Inertia Integral Truncation Order' (2) below the expansion's 4");
  refused("Secondary Shape Flag", "3", "'Secondary Shape Flag' = 3 is none of GUBAS's shapes");
  refused("Secondary Semi-Minor Axis", "90", "'Secondary Semi-Major Axis' and its semi-intermediate and semi-minor axes must not grow");
  refused("Final Time", "soon", "line 49: GUBAS option 'Final Time' 'soon' is not a finite number");
  refused("Final Time", "inf", "'Final Time' 'inf' is not a finite number");
  refused("Integrator Flag", "2.0", "'Integrator Flag' '2.0' is not a whole number");
  refused("B into A Euler Flag", "maybe", "'B into A Euler Flag' 'maybe' is not a flag");
  refused("Final Time", "7210.", "--T");  // not a whole number of 30 s steps: the run's own check
  auto o = didymos_example();
  set(o, "B into A Euler Flag", "0"), set(o, "B into A (1,1)", "2.0");
  BOOST_TEST(refusal(o).find("GUBAS options 'B into A (i,j)' do not form a rotation") != std::string::npos, refusal(o));
  BOOST_TEST(refusal(didymos_example(), "Final Time").find("GUBAS option 'Final Time' is missing") != std::string::npos);
  auto typo = didymos_example();
  typo[2].second.push_back({"Final Tme", "3"});
  BOOST_TEST(refusal(typo).find("GUBAS option 'Final Tme' is not one GUBAS reads in [Integration Settings]") != std::string::npos, refusal(typo));
  // a polyhedron's own lower order is raised to the expansion's, as GUBAS's driver does; an order
  // beyond what rotlie's expansion holds goes to --order as it is, for its own check
  auto raised = didymos_example();
  set(raised, "Primary Inertia Integral Truncation Order", "2");
  BOOST_TEST(mapped(raised).request.order == "4");
  auto higher = didymos_example();
  set(higher, "Gravity Expansion Truncation Order", "6"), set(higher, "Primary Inertia Integral Truncation Order", "6"),
      set(higher, "Secondary Inertia Integral Truncation Order", "6");
  BOOST_TEST(mapped(higher).request.order == "6");
  // RK 7(8) with its absolute tolerance
  auto adaptive = didymos_example();
  set(adaptive, "Integrator Flag", "3");
  BOOST_TEST(mapped(adaptive).request.integrator == "odeint-rkf78:1e-15");
}

BOOST_AUTO_TEST_SUITE_END()
