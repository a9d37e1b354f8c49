// The N integrators: Table 2 (spherical top, 12 real solutions, closed forms), Table 3 (analytic
// remainders as ratios to N5 (2)), Table 4 (water: 90 real solutions, coefficients to 35 digits,
// analytic remainders to the printed digits), residuals, and the RSRSRSR uniqueness of eq. (49).
#include <boost/test/unit_test.hpp>

#include <cln/real.h>
#include <cmath>
#include <map>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "solution_lookup.hpp"

BOOST_AUTO_TEST_SUITE(dedicated_schemes_test)

using namespace rotlie;
using cln::cl_RA;
using test::agrees_to_35_digits;
using test::find;
using test::number;
using test::value;

namespace {

const std::vector<std::string> n_schemes = {"N1", "N2", "N3", "N4", "N5", "N6", "N7"};
const int digits = 40;

const solver::family_result& sphere() {
  static const auto r = solver::solve_dedicated(lie::parse_moments("sphere"), n_schemes, {"ABC"}, digits);
  return r;
}
const solver::family_result& water() {
  static const auto r = solver::solve_dedicated(lie::parse_moments("water"), n_schemes, bch::permutation_names(), digits);
  return r;
}

cl_RA closed_form(const GiNaC::ex& e) {
  GiNaC::Digits = 60;
  return cln::rational(cln::the<cln::cl_R>(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_cl_N()));
}

}  // namespace

BOOST_AUTO_TEST_CASE(spherical_top_has_the_12_real_solutions_of_table_2) {
  const auto& r = sphere();
  BOOST_TEST(r.solutions.size() == 12u);
  std::map<std::string, int> per_scheme;
  for (const auto& s : r.solutions) ++per_scheme[s.scheme];
  BOOST_TEST(per_scheme["N1"] == 1);
  BOOST_TEST(per_scheme["N2"] == 1);
  BOOST_TEST(per_scheme["N3"] == 3);
  BOOST_TEST(per_scheme["N4"] == 3);
  BOOST_TEST(per_scheme["N5"] == 3);
  BOOST_TEST(per_scheme["N6"] == 0);
  BOOST_TEST(per_scheme["N7"] == 1);

  const GiNaC::ex pi = GiNaC::Pi, sqrt3 = GiNaC::sqrt(GiNaC::ex(3));
  const int k[] = {17, 7, 5};  // a1 = cos(kπ/18)/√3 for labels 1, 2, 3
  for (int label = 1; label <= 3; ++label) {
    const cl_RA a1 = closed_form(GiNaC::cos(k[label - 1] * pi / 18) / sqrt3);
    for (const char* scheme : {"N3", "N4", "N5"})
      BOOST_TEST(agrees_to_35_digits(value(find(r, scheme, "ABC", label), "a1"), a1), scheme << " (" << label << ") a1");
    BOOST_TEST(agrees_to_35_digits(value(find(r, "N3", "ABC", label), "b1"), cl_RA(3) / 2 - a1 - 6 * a1 * a1));
    BOOST_TEST(agrees_to_35_digits(value(find(r, "N4", "ABC", label), "b1"), cl_RA(1) / 2 - a1));
    BOOST_TEST(agrees_to_35_digits(value(find(r, "N5", "ABC", label), "c1"), cl_RA(-1) / 2 + 2 * a1 + 6 * a1 * a1));
  }
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N2", "ABC", 1), "a1"), cl_RA(1) / 6));
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N2", "ABC", 1), "a2"), cl_RA(1) / 6));
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N1", "ABC", 1), "a1"), number("-8.5120719195965763404768780897146082692210e-1")));
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N1", "ABC", 1), "b1"), number("-1.7560359597982881702384390448573041346105e-1")));
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N7", "ABC", 1), "b1"), number("6.7560359597982881702384390448573041346096e-1")));
  BOOST_TEST(agrees_to_35_digits(value(find(r, "N7", "ABC", 1), "c1"), number("1.3512071919596576340476878089714608269219")));
}

BOOST_AUTO_TEST_CASE(table_3_analytic_remainders_as_ratios_to_n5_2) {
  const auto& r = sphere();
  const double reference = find(r, "N5", "ABC", 2).analytic_remainder;
  const std::vector<std::tuple<std::string, int, double>> table3 = {
      {"N1", 1, 100.50}, {"N2", 1, 3.40}, {"N3", 1, 22.51}, {"N3", 2, 92.79}, {"N3", 3, 1.00}, {"N4", 1, 991.42},
      {"N4", 2, 1.58},   {"N4", 3, 1.18}, {"N5", 1, 92.79}, {"N5", 3, 22.51}, {"N7", 1, 100.50}};
  for (const auto& [scheme, label, want] : table3) {
    const double ratio = find(r, scheme, "ABC", label).analytic_remainder / reference;
    BOOST_TEST(std::abs(ratio - want) <= 0.005 + 1e-9, scheme << " (" << label << "): " << ratio << " vs " << want);
  }
}

BOOST_AUTO_TEST_CASE(water_has_90_real_solutions) {
  BOOST_TEST(water().solutions.size() == 90u);
  BOOST_TEST(water().systems.size() == 42u);
  for (const auto& s : water().systems) BOOST_TEST(!s.degenerate, s.scheme << " " << s.permutation);
}

BOOST_AUTO_TEST_CASE(every_row_of_table_4) {
  struct row {
    std::string scheme, perm;
    int label;
    std::string v1, v2;
    const char *x1, *x2;
    double remainder_e2;
  };
  const std::vector<row> table4 = {
      {"N1", "ABC", 1, "a1", "b1", "2.3009531403182120088035835866488791305526e-1", "2.7028961116588991802338916444296474989967e-1", 2.09},
      {"N1", "ABC", 2, "a1", "b1", "3.1275929803539412927331110867593240725096e-1", "1.8915198437863547818626148139249232203935e-1", 3.83},
      {"N2", "ABC", 1, "a1", "a2", "8.0232821323763118962115911006527082023129e-2", "6.6006740223496715389313719694385753827201e-2", 3.51},
      {"N2", "CAB", 2, "a1", "a2", "-6.9201301744275414774484171165883343266794e-2", "2.4031143347593460997280823526283232434071e-1", 2.91},
      {"N2", "ACB", 1, "a1", "a2", "2.6715152527177852877159258491775925759378e-1", "6.6006740223496715389313719694385753827201e-2", 1.18},
      {"N2", "BAC", 2, "a1", "a2", "4.5504624774591050429019276281136041301731e-2", "1.5208328361334726621353294430175796767150e-1", 1.06},
      {"N3", "ABC", 1, "a1", "b1", "1.3174008291685690570191318391432506966565e-1", "2.5001213925191940517879462955880090794685e-1", 2.77},
      {"N3", "BAC", 1, "a1", "b1", "2.3903848575720093321093271828856414366272e-2", "4.2282680933338933433781797072334937140324e-1", 2.96},
      {"N4", "BCA", 1, "a1", "b1", "2.2828507108154095724392719928157650301331e-1", "2.2825872461435056924300995377222198669807e-1", 3.22},
      {"N5", "CAB", 2, "a1", "c1", "-6.2720924052603008551218820536171143473233e-2", "1.7666303579793115034995233223175505593095e-1", 1.59},
      {"N5", "ACB", 1, "a1", "c1", "2.2739584699362931383103719281935592654238e-1", "2.4520662064421018140607329552267381194383e-1", 2.84},
      {"N5", "BAC", 1, "a1", "c1", "5.1047890551914167341876030732222399901020e-2", "2.2825872461435056924300995377222198669807e-1", 2.67},
      {"N6", "ABC", 1, "a1", "b1", "1.6014345007745294110506760786075550961823e-1", "3.3983727648480088011200434314807462997537e-1", 2.11},
      {"N6", "ABC", 2, "a1", "b1", "3.4036466230135420614475440479339320092178e-1", "1.6016272351519911988799565685192537002472e-1", 2.19},
      {"N6", "BAC", 1, "a1", "b1", "6.6786520394832546068432401466879049634959e-2", "4.3305225085804317378510080225902343232508e-1", 3.27}};
  for (const auto& t : table4) {
    const auto& s = find(water(), t.scheme, t.perm, t.label);
    BOOST_TEST_CONTEXT(s.name()) {
      BOOST_TEST(agrees_to_35_digits(value(s, t.v1), number(t.x1)));
      BOOST_TEST(agrees_to_35_digits(value(s, t.v2), number(t.x2)));
      BOOST_TEST(std::abs(s.analytic_remainder * 100 - t.remainder_e2) <= 0.005 + 1e-9, s.analytic_remainder * 100);
    }
  }
  // the best analytic remainder is N2 BAC (2), then N2 ACB (1), as the paper says
  BOOST_TEST(water().solutions[0].name() == "N2 BAC (2)");
  BOOST_TEST(water().solutions[1].name() == "N2 ACB (1)");
}

BOOST_AUTO_TEST_CASE(residuals_below_ten_to_minus_digits_minus_5) {
  const cl_RA bound = cln::recip(cln::expt(cl_RA(10), digits - 5));
  for (const auto* r : {&sphere(), &water()})
    for (const auto& s : r->solutions) BOOST_TEST((s.residual < bound), s.name());
}

BOOST_AUTO_TEST_CASE(rsrsrsr_has_only_yoshida_for_water) {
  // eq. (49): for an asymmetric body the only real solution is Yoshida's, b1 = 1/(2 − 2^(1/3)), a1 = b1/2.
  const auto r = solver::solve_dedicated(lie::parse_moments("water"), {"RSRSRSR", "SRSRSRS"}, {"ABC", "CBA"}, digits);
  BOOST_TEST(r.solutions.size() == 4u);
  const cl_RA yoshida = closed_form(1 / (2 - GiNaC::pow(2, GiNaC::numeric(1, 3))));
  for (const auto& s : r.solutions) {
    BOOST_TEST(agrees_to_35_digits(value(s, "b1"), yoshida), s.name());
    BOOST_TEST(agrees_to_35_digits(value(s, "a1"), yoshida / 2), s.name());
  }
}

BOOST_AUTO_TEST_CASE(rs_schemes_degenerate_for_a_symmetric_top) {
  // I1 = I2 makes R = G1²/2 (1/I1 − 1/I2) vanish: H_R3 ≡ 0 and nothing fixes the coefficients.
  const auto r = solver::solve_dedicated(lie::parse_moments("1,1,3/2"), {"RSRSRSR"}, {"ABC"}, digits);
  BOOST_REQUIRE(r.systems.size() == 1u);
  BOOST_TEST(r.systems[0].degenerate);
  BOOST_TEST(r.systems[0].note.find("I1 = I2") != std::string::npos, r.systems[0].note);
}

BOOST_AUTO_TEST_CASE(refusals) {
  BOOST_CHECK_THROW(solver::solve_dedicated(lie::parse_moments("water"), {"N9"}, {"ABC"}, digits), std::invalid_argument);
  BOOST_CHECK_THROW(solver::solve_dedicated(lie::parse_moments("water"), {"N1"}, {"XYZ"}, digits), std::invalid_argument);
  BOOST_CHECK_THROW(solver::solve_dedicated(lie::parse_moments("water"), {"N1"}, {"ABC"}, 5), std::invalid_argument);
  BOOST_CHECK_THROW(solver::solve_dedicated(lie::parse_moments("water"), {"P16"}, {"ABC"}, digits), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // dedicated_schemes_test
