// The held md scenes (issue 43): integrate(T/2) then integrate(T) equals integrate(T) bit for bit for
// every run of the ensemble, and run 0's final state equals the last sample of the scene's own run to
// T (run_scene with --every = T/h, the trajectory `rotlie md --json` prints); free water and the dipole
// in a field, several integrators and scalars; what cannot be held or asked is refused.
#include <boost/test/unit_test.hpp>

#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

#include "rotlie/runs/md_simulation.hpp"
#include "rotlie/runs/scenes.hpp"
#include "rotlie/runs/user_input.hpp"

BOOST_AUTO_TEST_SUITE(md_simulation_test)

using namespace rotlie;

namespace {

template <class A, class B>
bool same_bits(const A& a, const B& b) {
  static_assert(sizeof(A) == sizeof(B));
  return std::memcmp(&a, &b, sizeof(A)) == 0;
}

bool same_body(const runs::md_body& a, const runs::md_body& b) {
  return same_bits(a.q, b.q) && same_bits(a.p, b.p) && same_bits(a.Q, b.Q) && same_bits(a.G, b.G);
}

bool same_state(const runs::md_simulation& a, const runs::md_simulation& b) {
  if (a.steps() != b.steps() || a.systems() != b.systems() || a.bodies() != b.bodies() || !same_bits(a.t(), b.t())) return false;
  for (long s = 0; s < a.systems(); ++s) {
    if (!same_bits(a.energy(s), b.energy(s)) || !same_bits(a.potential(s), b.potential(s))) return false;
    for (long i = 0; i < a.bodies(); ++i)
      if (!same_body(a.body(s, i), b.body(s, i))) return false;
  }
  return a.force_evaluations() == b.force_evaluations();
}

// h in fs, T in ps (T/h whole steps), the ensemble of `runs`; extra options of the scene.
void check_continuation(const std::string& scene, const std::string& integrator, const std::string& h, double T, long steps,
                        std::map<std::string, std::string> options) {
  BOOST_TEST_CONTEXT(scene << " " << integrator << " " << (options.count("--scalar") ? options.at("--scalar") : "double")) {
    const runs::scene_request request{scene, integrator, h, options, {}};
    runs::md_simulation halves(request), whole(request);
    BOOST_TEST(halves.systems() == std::stol(options.at("--runs")));
    halves.integrate(T / 2);
    BOOST_TEST(halves.steps() == steps / 2);
    halves.integrate(T);
    whole.integrate(T);
    BOOST_TEST(whole.steps() == steps);
    BOOST_TEST(same_state(halves, whole));
    runs::md_simulation start(request);
    BOOST_TEST(!same_body(start.body(0, 0), whole.body(0, 0)));  // it moved

    // the scene's run to T, its trajectory sampled at the start and at T
    options["--T"] = std::to_string(T);
    options["--every"] = std::to_string(steps);
    const auto run = runs::run_scene({scene, integrator, h, options, {}}).json.at("trajectory");
    BOOST_TEST_REQUIRE(run.at("t_ps").size() == 2u);
    BOOST_TEST(same_bits(run.at("t_ps")[1].get<double>(), whole.t()));
    const auto b = whole.body(0, 0);
    for (std::size_t i = 0; i < 3; ++i) {
      BOOST_TEST(same_bits(run.at("G")[1][i].get<double>(), b.G[i]));
      for (std::size_t j = 0; j < 3; ++j) BOOST_TEST(same_bits(run.at("Q")[1][i][j].get<double>(), b.Q.a[3 * i + j]));
    }
    BOOST_TEST(same_bits(run.at("energy")[1].get<double>(), whole.energy(0)));
    BOOST_TEST(same_bits(run.at("potential")[1].get<double>(), whole.potential(0)));
    BOOST_TEST(same_bits(run.at("energy")[0].get<double>(), start.energy(0)));
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(free_water_continues_bit_for_bit) {
  check_continuation("free-water", "SIER4", "4", 0.4, 100, {{"--runs", "3"}, {"--seed", "7"}});
  check_continuation("free-water", "MRDL", "2", 0.1, 50, {{"--runs", "2"}, {"--scalar", "long-double"}});
}

BOOST_AUTO_TEST_CASE(dipole_field_continues_bit_for_bit) {
  check_continuation("dipole-field", "SIER4", "8", 0.8, 100, {{"--runs", "3"}});
  check_continuation("dipole-field", "SIER2", "4", 0.2, 50, {{"--runs", "2"}, {"--field", "5"}, {"--scalar", "float128"}});
}

BOOST_AUTO_TEST_CASE(targets_off_the_grid_and_in_the_past) {
  runs::md_simulation sim({"dipole-field", "SIER4", "2", {{"--runs", "1"}}, {}});
  sim.integrate(0.0105);  // 5.25 steps of 2 fs
  BOOST_TEST(sim.steps() == 5);
  BOOST_TEST(sim.t() == 0.01);
  sim.integrate(0.012);  // 6 h, 0.006 × 2 with round-off
  BOOST_TEST(sim.steps() == 6);
  BOOST_CHECK_THROW(sim.integrate(0.004), std::invalid_argument);
  BOOST_TEST(sim.steps() == 6);
  runs::md_simulation stepped({"dipole-field", "SIER4", "2", {{"--runs", "1"}}, {}});
  for (int k = 0; k < 6; ++k) stepped.step();
  BOOST_TEST(same_state(sim, stepped));
}

BOOST_AUTO_TEST_CASE(refusals) {
  BOOST_CHECK_THROW(runs::md_simulation({"free-water", "SIER4", "2", {{"--molecules", "400"}}, {}}), runs::bad_input);
  BOOST_CHECK_THROW(runs::md_simulation({"free-water", "NOPE", "2", {}, {}}), runs::bad_input);
  BOOST_CHECK_THROW(runs::md_simulation({"spin-orbit", "SIER4", "1/64", {{"--body", "Moon"}, {"--e", "0"}, {"--T", "1"}}, {}}),
                    runs::bad_input);
}

BOOST_AUTO_TEST_SUITE_END()  // md_simulation_test
