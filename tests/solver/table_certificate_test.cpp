// The certificate behind `order 4`: every table the solver writes certifies at its own decimals
// (read back from the text); the same table rounded to 6 digits, a coefficient perturbed at the
// 20th digit, or the coefficients of one body on another body, do not. The certificate is
// scale-free (the same residual for the body in any unit), and the written table keeps the body as
// given.
#include <boost/test/unit_test.hpp>

#include <cln/rational_io.h>
#include <cln/real.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/solver/table_certificate.hpp"

BOOST_AUTO_TEST_SUITE(table_certificate_test)

using namespace rotlie;
using cln::cl_RA;

namespace {

const int digits = 40;
cl_RA ten_to(int k) { return cln::expt(cl_RA(10), k); }

const lie::moments_of_inertia& water() {
  static const auto w = lie::parse_moments("water");
  return w;
}
const solver::family_result& n_water() {
  static const auto r = solver::solve_dedicated(water(), {"N1", "N2", "N3", "N4", "N5", "N6", "N7"},
                                                bch::permutation_names(), digits);
  return r;
}
const solver::dedicated_solution& n2_bac_2() {
  for (const auto& s : n_water().solutions)
    if (s.name() == "N2 BAC (2)") return s;
  throw std::logic_error("no N2 BAC (2)");
}

// The table text with every stage decimal replaced by its rounding to `keep` significant digits
// (the `digits` line still claims 40).
std::string rounded_stages(const std::string& text, int keep) {
  std::istringstream in(text);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("stage ", 0) == 0) {
      std::istringstream f(line);
      std::string tag, letter, name, decimal;
      f >> tag >> letter >> name >> decimal;
      line = tag + " " + letter + " " + name + " " + lie::to_decimal(*lie::parse_exact_number(decimal), keep);
    }
    out << line << "\n";
  }
  return out.str();
}

std::string line_of(const std::string& text, const std::string& key) {
  std::smatch m;
  BOOST_REQUIRE(std::regex_search(text, m, std::regex("\n" + key + " ([^\n]*)\n")));
  return m[1];
}

// The coefficient values with the free ones replaced and the eliminated ones solving the
// first-order conditions exactly again (so that only H_R3 can fail).
std::map<std::string, cl_RA> with_free(const solver::dedicated_solution& s, const std::map<std::string, cl_RA>& free) {
  std::map<std::string, cl_RA> v;
  for (const auto& [n, x] : free) v[n] = x;
  bch::solve_first_order_conditions(s.layout, v, [](const cl_RA& x, int n) { return x / n; });
  return v;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_written_table_certifies_order_4_at_its_own_decimals) {
  BOOST_TEST(n_water().solutions.size() == 90u);
  for (const auto& s : n_water().solutions) {
    const std::string text = solver::scheme_table_text(s, water(), digits);
    const auto c = solver::certify_scheme_table_text(text);
    BOOST_TEST_CONTEXT(s.name()) {
      BOOST_TEST(c.order == 4);
      BOOST_TEST(c.failure.empty());
      BOOST_TEST((c.residual <= solver::certificate_tolerance(digits)));
      BOOST_TEST(line_of(text, "order") == "4");
      BOOST_TEST(line_of(text, "residual") == lie::to_decimal(c.residual, 3));
    }
  }
}

BOOST_AUTO_TEST_CASE(six_digit_coefficients_do_not_certify_at_forty) {
  // Second method: the text itself rounded, certified as a reader would from the text alone.
  for (const auto& s : n_water().solutions) {
    const auto c = solver::certify_scheme_table_text(rounded_stages(solver::scheme_table_text(s, water(), digits), 6));
    BOOST_TEST(c.order < 4, s.name());
    BOOST_TEST((c.residual > ten_to(-12)), s.name());
    BOOST_TEST(!c.failure.empty());
  }
  // The free coefficients alone rounded to 6 digits, the others exact again: H_R3 fails, order 2.
  const auto& s = n2_bac_2();
  std::map<std::string, cl_RA> free;
  for (const auto& [n, x] : s.coefficients)
    if (std::find(s.free.begin(), s.free.end(), n) != s.free.end()) free[n] = solver::written_value(x, 6);
  const auto c = solver::certify_order_four(s.layout, water(), with_free(s, free), digits);
  BOOST_TEST(c.order == 2);
  BOOST_TEST(c.failure.find("H_R3") != std::string::npos, c.failure);
  // at 6 digits the same coefficients are what they claim
  BOOST_TEST(solver::certify_order_four(s.layout, water(), with_free(s, free), 9).order == 4);
}

BOOST_AUTO_TEST_CASE(a_perturbation_at_the_20th_digit_fails_at_40_digits_and_passes_at_15) {
  const auto& s = n2_bac_2();
  std::map<std::string, cl_RA> free;
  for (const auto& [n, x] : s.coefficients)
    if (std::find(s.free.begin(), s.free.end(), n) != s.free.end()) free[n] = x;
  free.at(s.free.front()) *= 1 + ten_to(-20);
  const auto values = with_free(s, free);
  const auto at40 = solver::certify_order_four(s.layout, water(), values, 40);
  BOOST_TEST(at40.order == 2);
  // a relative change of 1e-20 in one coefficient moves H_R3 by about that much of its terms
  BOOST_TEST((at40.residual > ten_to(-23)));
  BOOST_TEST((at40.residual < ten_to(-17)));
  BOOST_TEST(solver::certify_order_four(s.layout, water(), values, 15).order == 4);
}

BOOST_AUTO_TEST_CASE(one_bodys_coefficients_are_not_order_4_on_another_body) {
  const auto& s = n2_bac_2();
  const auto other = lie::parse_moments("0.4,0.7,1");
  const auto c = solver::certify_order_four(s.layout, other, solver::written_coefficients(s, digits), digits);
  BOOST_TEST(c.order == 2);
  BOOST_TEST((c.residual > ten_to(-3)));
}

BOOST_AUTO_TEST_CASE(the_certificate_and_the_table_are_scale_free) {
  const auto& s = n2_bac_2();
  const auto values = solver::written_coefficients(s, digits);
  const auto reference = solver::certify_order_four(s.layout, water(), values, digits);
  for (int k : {-100, 150}) {
    const lie::moments_of_inertia scaled{{water().I[0] * ten_to(k), water().I[1] * ten_to(k), water().I[2] * ten_to(k)}};
    const auto c = solver::certify_order_four(s.layout, scaled, values, digits);
    BOOST_TEST(c.order == 4);
    BOOST_TEST((c.residual == reference.residual));
    // the table of the scaled body: the body as given, the rest as for the unit body
    const auto result = solver::solve_dedicated(scaled, {"N2"}, {"BAC"}, digits);
    const auto it = std::find_if(result.solutions.begin(), result.solutions.end(),
                                 [](const auto& x) { return x.name() == "N2 BAC (2)"; });
    BOOST_REQUIRE((it != result.solutions.end()));
    const auto& t = *it;
    const std::string text = solver::scheme_table_text(t, scaled, digits);
    std::ostringstream inertia;
    inertia << scaled.I[0] << " " << scaled.I[1] << " " << scaled.I[2];
    BOOST_TEST(line_of(text, "inertia") == inertia.str());
    const std::string unit_text = solver::scheme_table_text(s, water(), digits);
    for (const char* key : {"order", "residual", "analytic_remainder"}) BOOST_TEST(line_of(text, key) == line_of(unit_text, key));
    BOOST_TEST(solver::certify_scheme_table_text(text).order == 4);
  }
}

BOOST_AUTO_TEST_CASE(malformed_tables_are_refused_with_a_reason) {
  const std::string good = solver::scheme_table_text(n2_bac_2(), water(), digits);
  BOOST_CHECK_THROW(solver::certify_scheme_table_text("format_version 1\n"), std::invalid_argument);
  BOOST_CHECK_THROW(solver::certify_scheme_table_text(std::regex_replace(good, std::regex("stage B a1 "), "stage C a1 ")),
                    std::invalid_argument);
  BOOST_CHECK_THROW(solver::certify_scheme_table_text(std::regex_replace(good, std::regex("\ndigits 40"), "\ndigits x")),
                    std::invalid_argument);
  // CRLF line ends are the same table
  BOOST_TEST(solver::certify_scheme_table_text(std::regex_replace(good, std::regex("\n"), "\r\n")).order == 4);
}

BOOST_AUTO_TEST_CASE(rs_and_three_free_coefficient_tables_certify_too) {
  // Yoshida's RSRSRSR (eq. 49) in the RS splitting, and P1 BAC, R ABC (three free coefficients).
  for (const auto& [scheme, perm] : std::vector<std::pair<std::string, std::string>>{
           {"RSRSRSR", "ABC"}, {"SRSRSRS", "CBA"}, {"P1", "BAC"}, {"R", "ABC"}}) {
    const auto r = solver::solve_dedicated(water(), {scheme}, {perm}, digits);
    BOOST_TEST(!r.solutions.empty(), scheme);
    for (const auto& s : r.solutions) {
      const std::string text = solver::scheme_table_text(s, water(), digits);
      BOOST_TEST(solver::certify_scheme_table_text(text).order == 4, s.name());
      BOOST_TEST(solver::certify_scheme_table_text(rounded_stages(text, 8)).order < 4, s.name());
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()  // table_certificate_test
