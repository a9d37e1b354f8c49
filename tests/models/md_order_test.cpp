// Orders of the torqued-body integrators on the dipole in a strong field (the kicks as large as
// the free flight), by the fitted slope of the step-doubling error e(h) = ‖y_h − y_{h/2}‖ at
// T = 200 fs (Richardson: e(h) = C hᵖ (1 − 2⁻ᵖ) + …, so its slope is the order p), h = 4 … 0.5 fs,
// three bodies. The outer TV table sets the order unless the rotor is worse: SIER2, MRDL in both axis orders,
// SEJ4 (a 4th-order rotor inside Strang) and SIER2/X are 2; SIER4 and SIER4 with a 4th-order rotor are 4;
// SIER4 with the 2nd-order leapfrog rotor drops to 2.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "md_support.hpp"

BOOST_AUTO_TEST_SUITE(md_order_test)

using namespace rotlie;

namespace {

double order_of(const std::string& name, std::vector<double>* errors = nullptr) {
  const double T = 200;
  const auto scene = test::dipole_scene<double>(test::strong_field<double>());
  const auto s0 = test::thermal_bodies<double>(3);
  std::vector<double> hs, es;
  for (long n = 50; n <= 400; n *= 2) {
    const double h = T / static_cast<double>(n);
    const auto coarse = test::run<double>(name, scene, s0, h, n);
    const auto fine = test::run<double>(name, scene, s0, h / 2, 2 * n);
    hs.push_back(h);
    es.push_back(test::state_distance(coarse, fine));
  }
  if (errors) *errors = es;
  return test::fitted_slope(hs, es);
}

void check_order(const std::string& name, int expected) {
  std::vector<double> e;
  const double p = order_of(name, &e);
  BOOST_TEST_MESSAGE(name << ": slope " << p << ", e(4 fs) = " << e.front() << ", e(0.5 fs) = " << e.back());
  BOOST_TEST(std::abs(p - expected) < 0.15, name << " slope " << p << " (expected " << expected << ")");
  BOOST_TEST(e.back() > 1e-11, name << ": the smallest error must stay above the exact flow's accuracy");
}

}  // namespace

BOOST_AUTO_TEST_CASE(second_order_integrators) {
  for (const char* name : {"SIER2", "MRDL", "MRDL-reversed", "SEJ4", "SIER2/RS4-S5-McLachlan:CBA", "SIER2/ABCBA4-SS3-Yoshida:ABC"}) check_order(name, 2);
}

BOOST_AUTO_TEST_CASE(fourth_order_integrators) {
  for (const char* name : {"SIER4", "SIER4/RS4-S5-McLachlan:CBA", "SIER4/ABCBA4-SS3-Yoshida:ABC"}) check_order(name, 4);
}

BOOST_AUTO_TEST_CASE(a_second_order_rotor_limits_sier4) { check_order("SIER4/ABCBA2:CBA", 2); }

BOOST_AUTO_TEST_CASE(the_field_matters) {
  // with the field off, SIER2 is exact up to the exact flow: its error is far below the field's
  const auto s0 = test::thermal_bodies<double>(3);
  const auto off = test::dipole_scene<double>(0.0);
  const auto on = test::dipole_scene<double>(test::strong_field<double>());
  const double e_off = test::state_distance(test::run<double>("SIER2", off, s0, 2.0, 100), test::run<double>("SIER2", off, s0, 1.0, 200));
  const double e_on = test::state_distance(test::run<double>("SIER2", on, s0, 2.0, 100), test::run<double>("SIER2", on, s0, 1.0, 200));
  BOOST_TEST_MESSAGE("SIER2 step-doubling error, field off " << e_off << ", on " << e_on);
  BOOST_TEST(e_off < 1e-9);
  BOOST_TEST(e_on > 1e-4);
}

BOOST_AUTO_TEST_SUITE_END()  // md_order_test
