// What binary_setup_of makes of a request (issue 46): a preset's numbers arrive as the doubles they are,
// never through text, and --T 0 evaluates any pose, even one whose future orbit would collide.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "rotlie/runs/binary_bodies.hpp"
#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/user_input.hpp"

BOOST_AUTO_TEST_SUITE(binary_setup_test)

using namespace rotlie;

namespace {

runs::binary_request didymos_request() {
  runs::binary_request r;
  r.system = "didymos", r.integrator = "SIER4", r.h = "60", r.T = "0";
  return r;
}

// The pair at rest 1.2 km apart, frames aligned: its future is a fall into contact.
const std::string pose_at_rest =
    R"({"r": [1.2, 0, 0], "v": [0, 0, 0], "Q1": [[1,0,0],[0,1,0],[0,0,1]], "Q2": [[1,0,0],[0,1,0],[0,0,1]], "omega1": [0,0,0], "omega2": [0,0,0]})";

}  // namespace

BOOST_AUTO_TEST_CASE(a_presets_masses_are_its_documented_densitys_bit_for_bit) {
  const auto& preset = runs::binary_system_named("didymos");
  const auto s = runs::binary_setup_of(didymos_request());
  // the documented density, 2203.111036687207 kg/m³ (the GUBAS example's), times each body's volume
  const double rho = 2203.111036687207;
  BOOST_TEST(preset.density1 == rho);
  const auto primary = runs::with_density(runs::binary_shape_named(preset.primary, "--primary"), rho);
  const auto secondary = runs::with_density(runs::binary_shape_named(preset.secondary, "--secondary"), rho);
  BOOST_TEST(s.primary.body.mass == primary.body.mass);  // bit for bit (the text path gave 2203.11: 4.7e-7 low)
  BOOST_TEST(s.secondary.body.mass == secondary.body.mass);
  BOOST_TEST(s.primary.density == rho);
  BOOST_TEST(s.secondary.density == rho);
  // the same request with the density given as its full text
  auto given = didymos_request();
  given.density = "2203.111036687207";
  const auto t = runs::binary_setup_of(given);
  BOOST_TEST(t.primary.body.mass == s.primary.body.mass);
  BOOST_TEST(t.start.v[1] == s.start.v[1]);  // so the circular start's rate too
}

BOOST_AUTO_TEST_CASE(the_presets_start_is_its_separation_and_spin_unrounded) {
  const auto& preset = runs::binary_system_named("didymos");
  const auto s = runs::binary_setup_of(didymos_request());
  BOOST_TEST(s.start.r[0] == preset.separation);
  const double spin = s.start.body[0].G[2] / s.primary.body.inertia(2, 2);
  BOOST_TEST(spin == 2 * std::acos(-1.0) / (3600 * preset.primary_period), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(T_0_evaluates_a_pose_at_rest_that_a_run_refuses) {
  auto r = didymos_request();
  r.state_text = pose_at_rest;
  const auto s = runs::binary_setup_of(r);
  const auto x = runs::binary_run(s);
  BOOST_TEST(x.end.t == 0.0);
  BOOST_TEST(x.mutual.U < 0);  // the pose's mutual values
  r.T = "600";
  BOOST_CHECK_THROW(runs::binary_setup_of(r), runs::bad_input);  // its future collides: a run is refused
}

BOOST_AUTO_TEST_SUITE_END()
