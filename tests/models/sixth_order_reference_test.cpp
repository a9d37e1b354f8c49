// The general 6th-order compositions (schemes/reference_schemes): each has a fitted slope of 6 ± 0.1 in
// float128 on water in every permutation; the compositions' γ meet the order conditions that every
// symmetric 6th-order composition of a symmetric step must meet (Σγ = 1, Σγ³ = Σγ⁵ = 0, McLachlan 1995);
// every table is a palindrome whose parts each sum to 1.
#include <boost/test/unit_test.hpp>

#include "model_support.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

BOOST_AUTO_TEST_SUITE(sixth_order_reference_test)

using namespace rotlie;
using rotlie::quad;

namespace {

double slope(const schemes::scheme_table& t, const models::vec3<quad>& I) {
  return models::measure_order<quad>(t, I, test::initial_state<quad>({quad(1), quad(1), quad(1)}), quad(1), 4, 8, 5).slope;
}

double size(const quad& x) { return static_cast<double>(abs(x)); }

}  // namespace

BOOST_AUTO_TEST_CASE(every_composition_is_of_order_six_in_every_permutation) {
  const auto water = test::water_moments<quad>();
  BOOST_TEST(schemes::reference_sixth_order_scheme_names().size() == 8u);
  for (const auto& name : schemes::reference_sixth_order_scheme_names())
    for (const char* p : {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"}) {
      const auto t = *schemes::reference_scheme(name + ":" + p);
      BOOST_TEST(t.order == 6);
      const double s = slope(t, water);
      BOOST_TEST(std::abs(s - 6) < 0.1, t.name << " slope " << s);
    }
}

BOOST_AUTO_TEST_CASE(tables_are_palindromes_whose_parts_sum_to_one) {
  for (const auto& name : schemes::reference_sixth_order_scheme_names()) {
    const auto t = *schemes::reference_scheme(name);
    BOOST_CHECK_NO_THROW(schemes::check_scheme_table(t));
    const std::size_t n = t.stages.size();
    for (std::size_t i = 0; i < n; ++i) {
      BOOST_TEST(t.stages[i].part == t.stages[n - 1 - i].part, name);
      BOOST_TEST(size(quad(t.stages[i].value) - quad(t.stages[n - 1 - i].value)) < 1e-30, name);
    }
  }
}

BOOST_AUTO_TEST_CASE(composition_weights_meet_the_necessary_order_conditions) {
  // In RSR6-…, the S stages carry the weights γ1 … γs of the composed leapfrogs.
  for (const char* name : {"RSR6-SS9-Yoshida", "RSR6-SS7-Yoshida", "RSR6-SS9-KahanLi"}) {
    const auto t = *schemes::reference_scheme(name);
    quad sum1 = 0, sum3 = 0, sum5 = 0;
    for (const auto& s : t.stages)
      if (s.part == 'S') {
        const quad g(s.value);
        sum1 += g, sum3 += g * g * g, sum5 += g * g * g * g * g;
      }
    BOOST_TEST(size(sum1 - 1) < 1e-30, name);
    // Yoshida's triple jump is exact; the others are printed with 20 digits.
    const double tolerance = std::string(name) == "RSR6-SS9-Yoshida" ? 1e-30 : 1e-18;
    BOOST_TEST(size(sum3) < tolerance, name << " Σγ³ = " << sum3);
    BOOST_TEST(size(sum5) < tolerance, name << " Σγ⁵ = " << sum5);
  }
}

BOOST_AUTO_TEST_CASE(the_abc_form_of_blanes_moan_is_the_adjoint_composition_of_the_rs_form) {
  // φ(α1) φ*(α2) …: the A stages of ABC6 carry α1, α2 + α3, …; each part sums to 1 like the RS form's.
  const auto rs = *schemes::reference_scheme("RS6-S10-BlanesMoan"), abc = *schemes::reference_scheme("ABC6-S10-BlanesMoan");
  BOOST_TEST(rs.stages.size() == 21u);
  BOOST_TEST(abc.stages.size() == 41u);
  BOOST_TEST(abc.word.front() == 'A');
  // The first stage of both is the first two-part coefficient, b1 of Blanes & Moan.
  BOOST_TEST(size(quad(rs.stages[0].value) - quad(abc.stages[0].value)) < 1e-30);
}

BOOST_AUTO_TEST_SUITE_END()  // sixth_order_reference_test
