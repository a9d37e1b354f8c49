// The binary scene held as a simulation (runs/binary_simulation.hpp): integrate(T/2) then
// integrate(T) is one run to T bit for bit, for every family of integrator (a splitting with its
// carried forces, the Kepler split, RK4, LGVI with its carried forces, Odeint with its carried step),
// a copy saves everything a continuation needs, and binary_run is one integrate.
#include <boost/test/unit_test.hpp>

#include <cstring>
#include <stdexcept>
#include <string>

#include "rotlie/runs/binary_simulation.hpp"

BOOST_AUTO_TEST_SUITE(binary_simulation_test)

using namespace rotlie;

namespace {

runs::binary_setup didymos(const std::string& integrator, const std::string& order, const std::string& h, const std::string& T) {
  runs::binary_request r;
  r.system = "didymos", r.integrator = integrator, r.order = order, r.h = h, r.T = T;
  return runs::binary_setup_of(r);
}

bool same_bits(const models::binary_state<double>& a, const models::binary_state<double>& b) {
  bool same = std::memcmp(a.r.data(), b.r.data(), sizeof(double) * 3) == 0 && std::memcmp(a.v.data(), b.v.data(), sizeof(double) * 3) == 0;
  for (int i = 0; i < 2; ++i)
    same = same && std::memcmp(a.body[i].Q.a.data(), b.body[i].Q.a.data(), sizeof(double) * 9) == 0 &&
           std::memcmp(a.body[i].G.data(), b.body[i].G.data(), sizeof(double) * 3) == 0;
  return same;
}

const char* const families[][2] = {{"SIER4", "2"}, {"KEPLER4", "4"}, {"SIER6", "2"}, {"RK4", "2"}, {"LGVI", "4"}, {"odeint-rkf78:1e-10", "2"}};

}  // namespace

BOOST_AUTO_TEST_CASE(integrating_in_two_calls_is_one_run_bit_for_bit) {
  for (const auto& [integrator, order] : families) {
    const auto setup = didymos(integrator, order, "120", "43200");
    const auto whole = runs::binary_run(setup);
    runs::binary_simulation sim(setup);
    sim.integrate(21600);
    BOOST_TEST(sim.steps() == 180);
    sim.integrate(43200);
    BOOST_TEST_INFO(integrator);
    BOOST_TEST(sim.steps() == setup.steps);
    BOOST_TEST(same_bits(sim.state(), whole.end.x));
    // the count of evaluations and the conserved quantities' errors at the end agree too
    BOOST_TEST(sim.result().evaluations == whole.evaluations);
    BOOST_TEST(sim.result().end.energy == whole.end.energy);
  }
}

BOOST_AUTO_TEST_CASE(a_copy_saves_and_restores_the_whole_simulation) {
  for (const auto& [integrator, order] : families) {
    runs::binary_simulation sim(didymos(integrator, order, "120", "43200"));
    sim.integrate(10800);
    const runs::binary_simulation saved = sim;
    sim.integrate(43200);
    const auto end = sim.state();
    sim = saved;
    BOOST_TEST(sim.t() == 10800.0);
    sim.integrate(43200);
    BOOST_TEST_INFO(integrator);
    BOOST_TEST(same_bits(sim.state(), end));
  }
}

BOOST_AUTO_TEST_CASE(steps_one_by_one_are_the_same_steps) {
  const auto setup = didymos("SIER4", "2", "120", "3600");
  runs::binary_simulation a(setup), b(setup);
  a.integrate(3600);
  for (int k = 0; k < 30; ++k) b.step();
  BOOST_TEST(same_bits(a.state(), b.state()));
  BOOST_TEST(b.t() == 3600.0);
}

BOOST_AUTO_TEST_CASE(a_time_between_steps_takes_the_steps_that_end_before_it) {
  runs::binary_simulation sim(didymos("SIER4", "2", "120", "3600"));
  sim.integrate(1000);  // 8 steps end at 960 s, the 9th at 1080 s
  BOOST_TEST(sim.steps() == 8);
  BOOST_TEST(sim.t() == 960.0);
  sim.integrate(960);  // already there: no step
  BOOST_TEST(sim.steps() == 8);
  BOOST_CHECK_THROW(sim.integrate(100), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
