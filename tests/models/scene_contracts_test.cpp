// The scene contracts (scene_contracts.hpp) as compile-time checks: today's potentials, rotors,
// system and observers satisfy them, and things that are not one of them are refused; the two
// instances of units as data.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/free_rigid_body.hpp"
#include "rotlie/models/scene_contracts.hpp"
#include "rotlie/models/scenes/dipole_in_field.hpp"
#include "rotlie/models/scenes/liquid_water.hpp"
#include "rotlie/models/scenes/zero_potential.hpp"
#include "rotlie/models/sej4_rotor.hpp"
#include "rotlie/models/table_rotor.hpp"
#include "rotlie/models/torqued_rigid_bodies.hpp"
#include "rotlie/models/unit_system.hpp"

BOOST_AUTO_TEST_SUITE(scene_contracts_test)

using namespace rotlie::models;

namespace {

using bodies = std::vector<rigid_body_state<double>>;
using vectors = std::vector<vec3<double>>;

struct clock_potential {  // V(x, t) = t, no force
  bool acts() const { return true; }
  double evaluate(const bodies&, vectors&, vectors&, const double& t) const { return t; }
};
struct without_acts {
  double evaluate(const bodies&, vectors&, vectors&) const { return 0; }
};
struct without_evaluate {
  bool acts() const { return false; }
};

struct rotor_without_moments {
  void advance(body_state<double>&, const double&) const {}
};

using state = rigid_bodies_state<double>;
auto void_observer = [](long, const double&, const state&) {};
auto stopping_observer = [](long, const double&, const state&) { return true; };
auto counting_observer = [](long k, const double&, const state&) { return k; };  // neither void nor bool
auto free_body_observer = [](long, const double&, const body_state<double>&) {};

}  // namespace

// potentials: the three of the scenes (time-independent), and one that reads the time
static_assert(torque_potential<zero_potential<double>, double>);
static_assert(torque_potential<dipole_in_field<double>, double>);
static_assert(torque_potential<liquid_water<double>, double>);
static_assert(time_independent_potential<dipole_in_field<double>, double> && !time_dependent_potential<dipole_in_field<double>, double>);
static_assert(torque_potential<clock_potential, double> && time_dependent_potential<clock_potential, double>);
static_assert(!torque_potential<without_acts, double>);
static_assert(!torque_potential<without_evaluate, double>);
static_assert(!torque_potential<dipole_in_field<double>, long double>);  // a potential of another scalar

// rotors: the exact flow, a scheme table, SEJ4's
static_assert(free_rotor<exact_free_rotation<double>, double>);
static_assert(free_rotor<table_rotor<double>, double>);
static_assert(free_rotor<sej4_rotor<double>, double>);
static_assert(!free_rotor<rotor_without_moments, double>);
static_assert(!free_rotor<zero_potential<double>, double>);

// systems: bodies under torques are one; the free body is a splitting system but not of rigid bodies with forces
static_assert(rigid_body_system<torqued_rigid_bodies<double, dipole_in_field<double>, exact_free_rotation<double>>>);
static_assert(rigid_body_system<torqued_rigid_bodies<double, clock_potential, table_rotor<double>>>);
static_assert(splitting_system<free_rigid_body<double>> && !rigid_body_system<free_rigid_body<double>>);

// observers
static_assert(run_observer<decltype(void_observer), state, double>);
static_assert(run_observer<decltype(stopping_observer), state, double>);
static_assert(!run_observer<decltype(counting_observer), state, double>);
static_assert(!run_observer<decltype(free_body_observer), state, double>);
static_assert(run_observer<decltype(free_body_observer), body_state<double>, double>);

BOOST_AUTO_TEST_CASE(a_time_independent_potential_is_called_without_the_time) {
  const dipole_in_field<double> dipole(0.4, 1, {0, 0, 0.5});
  bodies b(1);
  vectors f(1), tau(1), f2(1), tau2(1);
  const double V = potential_at(dipole, b, f, tau, 123.0), V0 = dipole.evaluate(b, f2, tau2);
  BOOST_TEST(V == V0);
  BOOST_TEST(tau[0][0] == tau2[0][0]);
  BOOST_TEST(potential_at(clock_potential{}, b, f, tau, 2.5) == 2.5);
}

BOOST_AUTO_TEST_CASE(units_are_data_real_and_natural) {
  const auto real = unit_system<double>::real();
  BOOST_TEST(real.ftm2v == real_units::ftm2v<double>());  // the same factor the kicks always used
  BOOST_TEST(real.mvv2e == real_units::mvv2e<double>());
  BOOST_TEST(std::string(real.time) == "fs");
  BOOST_TEST(std::string(real.energy) == "kcal/mol");
  const auto natural = unit_system<double>::natural();
  BOOST_TEST(natural.ftm2v == 1.0);
  BOOST_TEST(natural.mvv2e == 1.0);
  BOOST_TEST(std::string(natural.name) == "natural");
}

BOOST_AUTO_TEST_CASE(a_body_of_an_unknown_type_is_refused) {
  using system = torqued_rigid_bodies<double, zero_potential<double>, exact_free_rotation<double>>;
  const vec3<double> I{1, 2, 2.5};
  const system sys(2.0, I, zero_potential<double>{}, exact_free_rotation<double>(I));
  state s;
  s.bodies.resize(2);
  s.bodies[1].type = 1;
  BOOST_CHECK_THROW(sys.free_flight(0.1, s), std::out_of_range);
  BOOST_CHECK_THROW(system({}, zero_potential<double>{}, unit_system<double>::natural()), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // scene_contracts_test
