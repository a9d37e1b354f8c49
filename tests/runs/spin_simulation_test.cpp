// The held spin–orbit run (issue 43): integrate(T/2) then integrate(T) equals integrate(T) bit for bit,
// and both equal spin_run's final state (the run of `rotlie spin`), for a splitting in each scalar and
// for an Odeint method; targets off the step grid, and a target in the past refused.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "rotlie/runs/spin_orbit_run.hpp"
#include "rotlie/runs/spin_simulation.hpp"

BOOST_AUTO_TEST_SUITE(spin_simulation_test)

using namespace rotlie;

namespace {

runs::spin_setup setup_of(const std::string& integrator, const std::string& h, const std::string& T, const std::string& scalar = "double") {
  return runs::spin_setup_of({"Hyperion", "0.1", integrator, h, T, "0.3", "1.5", "0.2", scalar});
}

template <class A, class B>
bool same_bits(const A& a, const B& b) {
  static_assert(sizeof(A) == sizeof(B));
  return std::memcmp(&a, &b, sizeof(A)) == 0;
}

bool same_state(const runs::spin_simulation& a, const runs::spin_simulation& b) {
  return same_bits(a.Q(), b.Q()) && same_bits(a.G(), b.G()) && same_bits(a.omega_body(), b.omega_body()) &&
         same_bits(a.energy(), b.energy()) && a.evaluations() == b.evaluations() && a.steps() == b.steps() && same_bits(a.t(), b.t());
}

// Halves, whole and spin_run, to T.
void check_continuation(const runs::spin_setup& s) {
  BOOST_TEST_CONTEXT(s.method.name << " in " << s.scalar) {
    runs::spin_simulation halves(s), whole(s);
    halves.integrate(s.T / 2);
    BOOST_TEST(halves.steps() == s.steps / 2);
    halves.integrate(s.T);
    whole.integrate(s.T);
    BOOST_TEST(whole.steps() == s.steps);
    BOOST_TEST(whole.t() == s.T);
    BOOST_TEST(same_state(halves, whole));
    const auto r = runs::spin_run(s);
    BOOST_TEST(same_bits(whole.Q(), r.Q));
    BOOST_TEST(same_bits(whole.omega_body(), r.omega_body));
    BOOST_TEST(same_bits(whole.theta(), r.theta));
    BOOST_TEST(same_bits(whole.energy(), r.energy_end));
    BOOST_TEST(whole.evaluations() == r.evaluations);
    // the run moved: not the start
    runs::spin_simulation start(s);
    BOOST_TEST(!same_bits(start.Q(), whole.Q()));
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(splitting_continues_bit_for_bit) {
  check_continuation(setup_of("SIER4", "1/64", "2"));
  check_continuation(setup_of("MRDL", "0.01", "1"));  // h = T/steps rounded: the same step as spin_run's
  check_continuation(setup_of("SIER2", "1/32", "1", "long-double"));
  check_continuation(setup_of("SIER4", "1/16", "1/2", "float128"));
}

BOOST_AUTO_TEST_CASE(odeint_continues_bit_for_bit) {
  check_continuation(setup_of("odeint-dopri5:1e-10", "1/32", "1"));
  check_continuation(setup_of("odeint-rkf78:1e-12", "1/16", "1", "long-double"));
}

BOOST_AUTO_TEST_CASE(steps_one_at_a_time) {
  const auto s = setup_of("SIER4", "1/64", "1/2");
  runs::spin_simulation stepped(s), whole(s);
  for (long k = 0; k < s.steps; ++k) stepped.step();
  whole.integrate(0.5);
  BOOST_TEST(same_state(stepped, whole));
}

BOOST_AUTO_TEST_CASE(targets_off_the_grid_and_in_the_past) {
  const auto s = setup_of("SIER4", "1/64", "1");
  runs::spin_simulation sim(s);
  sim.integrate(10.5 / 64);  // between steps 10 and 11: the steps ending at or before t
  BOOST_TEST(sim.steps() == 10);
  BOOST_TEST(sim.t() == 10.0 / 64);
  sim.integrate(std::nextafter(11.0 / 64, 0.0));  // an ulp short of step 11's end: round-off, step 11 taken
  BOOST_TEST(sim.steps() == 11);
  sim.integrate(sim.t());  // now: nothing to do
  BOOST_TEST(sim.steps() == 11);
  BOOST_CHECK_THROW(sim.integrate(5.0 / 64), std::invalid_argument);
  BOOST_CHECK_THROW(sim.integrate(std::nan("")), std::invalid_argument);
  BOOST_TEST(sim.steps() == 11);
  runs::spin_simulation again(s);
  for (int k = 0; k < 11; ++k) again.step();
  BOOST_TEST(same_state(sim, again));
}

BOOST_AUTO_TEST_CASE(stop_ends_at_a_whole_step) {
  const auto s = setup_of("SIER4", "1/64", "1");
  runs::spin_simulation sim(s), whole(s);
  long asked = 0;
  sim.integrate(1, [&] { return ++asked > 20; });
  BOOST_TEST(sim.steps() == 20);
  sim.integrate(1);
  whole.integrate(1);
  BOOST_TEST(same_state(sim, whole));
}

BOOST_AUTO_TEST_SUITE_END()  // spin_simulation_test
