// ICQ shape models (Gaskell's format) through `polyhedron:FILE`: an ellipsoid written as ICQ reads as a
// closed, outward mesh of 6Q² + 2 vertices and 12Q² facets whatever way its faces turn, its mass and
// inertia converge to the ellipsoid's at second order in the edge (Q = 8, 16, 32), and files that are
// not ICQ models are refused in one line naming what is wrong.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

#include "icq_ellipsoid.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/runs/binary_bodies.hpp"
#include "rotlie/runs/user_input.hpp"

BOOST_AUTO_TEST_SUITE(icq_shape_test)

using namespace rotlie;
namespace fs = std::filesystem;

namespace {

constexpr double a = 0.42, b = 0.40, c = 0.37, density = 2000;  // km, kg/m³

fs::path written(const std::string& name, const std::string& text) {
  static const fs::path dir = [] {
    const auto d = fs::temp_directory_path() / ("rotlie-icq-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The message parse_shape_model refuses `text` with (empty if it reads).
std::string refusal(const std::string& text) {
  try {
    runs::parse_shape_model(text, "--primary x.icq");
  } catch (const runs::bad_input& e) {
    return e.what();
  }
  return "";
}

std::string ellipsoid_lines(int q) { return test_support::icq_ellipsoid_text(q, a, b, c); }

}  // namespace

BOOST_AUTO_TEST_CASE(an_icq_ellipsoid_is_a_closed_outward_mesh_either_way_its_faces_turn) {
  for (const bool mirrored : {false, true}) {
    const int q = 8;
    const auto p = runs::parse_shape_model(test_support::icq_ellipsoid_text(q, a, b, c, mirrored), "--primary x.icq");
    BOOST_TEST(p.vertices.size() == std::size_t(6 * q * q + 2));
    BOOST_TEST(p.facets.size() == std::size_t(12 * q * q));
    // polyhedron_body refuses an open, inverted or inconsistently turned mesh; this one is taken whole
    const auto body = models::polyhedron_body<double>(p, 1.0);
    BOOST_TEST(body.volume > 0.9 * 4 * std::numbers::pi / 3 * a * b * c, "mirrored " << mirrored);
  }
}

// Inscribed in the ellipsoid, the mesh misses a shell of thickness ∝ edge²: halving the edge (Q doubled)
// divides the mass's and the inertia's errors by about 4.
BOOST_AUTO_TEST_CASE(mass_and_inertia_converge_to_the_ellipsoids_at_second_order) {
  const double M = density * 1e9 * 4 * std::numbers::pi / 3 * a * b * c;
  const auto exact = models::ellipsoid_body(M, a, b, c);
  double previous[2] = {0, 0};
  for (const int q : {8, 16, 32}) {
    const auto file = written("ellipsoid-" + std::to_string(q) + ".icq", ellipsoid_lines(q));
    const auto body = runs::with_density(runs::binary_shape_named("polyhedron:" + file.string(), "--primary"), density);
    double inertia_error = 0;
    for (int k = 0; k < 3; ++k)
      inertia_error = std::max(inertia_error, std::abs(body.body.inertia(k, k) - exact.inertia(k, k)) / exact.inertia(k, k));
    const double errors[2] = {std::abs(body.body.mass - M) / M, inertia_error};
    BOOST_TEST_MESSAGE("Q = " << q << ": relative errors of the mass " << errors[0] << ", of the inertia " << errors[1]);
    BOOST_TEST(errors[0] < 0.1);
    if (q > 8)
      for (int k = 0; k < 2; ++k) {
        const double ratio = previous[k] / errors[k];
        BOOST_TEST((ratio > 3.6 && ratio < 4.4), "Q = " << q << ", integral " << k << ": ratio " << ratio);
      }
    previous[0] = errors[0], previous[1] = errors[1];
  }
}

BOOST_AUTO_TEST_CASE(what_is_not_an_icq_model_is_refused_in_one_line) {
  const auto good = ellipsoid_lines(2);
  BOOST_TEST(refusal(good).empty());
  const auto refused_with = [](const std::string& text, const std::string& part) {
    const auto why = refusal(text);
    BOOST_TEST(why.find(part) != std::string::npos, "'" << why << "' lacks '" << part << "'");
    BOOST_TEST(why.find('\n') == std::string::npos);
  };
  // truncated: a line short of 6(Q+1)² = 54
  refused_with(good.substr(0, good.rfind('\n', good.size() - 2) + 1), "6(Q+1)^2 = 54 vertex lines, this file 53");
  refused_with(good + "0 0 0\n", "this file 55");
  refused_with("0\n", "Q = 0 is out of range");
  refused_with("100000\n1 2 3\n", "Q = 100000 is out of range");
  refused_with("-3\n", "Q = -3 is out of range");
  auto replaced = [&](int line, const std::string& with) {  // `line` counted from 1, Q's line included
    std::string t = good;
    std::size_t start = 0;
    for (int k = 1; k < line; ++k) start = t.find('\n', start) + 1;
    return t.replace(start, t.find('\n', start) - start, with);
  };
  refused_with(replaced(20, "0.1 zero 0.2"), "line 20: vertex coordinate 'zero' is not a number");
  refused_with(replaced(20, "0.1 nan 0.2"), "line 20: vertex coordinate nan is not finite");
  refused_with(replaced(20, "0.1 inf 0.2"), "line 20: vertex coordinate inf is not finite");
  refused_with(replaced(20, "0.1 0.2"), "line 20: a vertex needs three finite coordinates");
  refused_with(replaced(20, "0.1 0.2 0.3 0.4"), "line 20: an ICQ vertex line holds three numbers");
  // line 2 is v(0,0,1), a corner: its copies are v(0,0,3) and v(2,0,4), on lines 20 and 31
  refused_with(replaced(20, "0.1 0.2 0.3"), "line 20: the faces' shared vertex written on line 2 is written differently here");
  // every vertex on one point: no volume
  std::string flat = "2\n";
  for (int k = 0; k < 54; ++k) flat += "1 1 1\n";
  refused_with(flat, "encloses no volume");
}

BOOST_AUTO_TEST_SUITE_END()
