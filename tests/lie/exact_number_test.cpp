// Exact numbers from text and rigid-body moments: parsing, refusals, eq. (77).
#include <boost/test/unit_test.hpp>

#include <cln/integer.h>
#include <cln/rational_io.h>

#include <sstream>

#include <string>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/rigid_body.hpp"

BOOST_AUTO_TEST_SUITE(exact_number_test)

using namespace rotlie::lie;

namespace {
bool parses_to(const char* text, const cln::cl_RA& want) {
  const auto v = parse_exact_number(text);
  return v && *v == want;
}
}  // namespace

BOOST_AUTO_TEST_CASE(exact_values) {
  BOOST_TEST(parses_to("3", 3));
  BOOST_TEST(parses_to("-1/3", cln::cl_RA(-1) / 3));
  BOOST_TEST(parses_to("10220/29376", cln::cl_RA(10220) / 29376));
  BOOST_TEST(parses_to("0.348", cln::cl_RA(348) / 1000));
  BOOST_TEST(parses_to("3.48e-1", cln::cl_RA(348) / 1000));
  BOOST_TEST(parses_to("+2.5E+3", 2500));
  BOOST_TEST(parses_to(" 1.5 ", cln::cl_RA(3) / 2));
  BOOST_TEST(parses_to(".5", cln::cl_RA(1) / 2));
  BOOST_TEST(parses_to("1.5/0.5", 3));
}

BOOST_AUTO_TEST_CASE(malformed_text_is_refused) {
  for (const char* bad : {"", "nan", "NaN", "inf", "-inf", "1/0", "abc", "1.2.3", "1e", "1e+", "--1", "1/2/3", "sin()",
                          "0x10", "1e999999", "2,3", "1 2"})
    BOOST_TEST(!parse_exact_number(bad).has_value(), "'" << bad << "'");
}

BOOST_AUTO_TEST_CASE(overflowing_numbers_are_refused_with_the_reason) {
  auto problem = [](const std::string& text) { return parse_exact_number_checked(text).problem; };
  const std::string digits400(400, '7'), digits1000(1000, '7');
  // the stated range: 0, or a magnitude in [1e-400, 1e400], fractions included
  for (const char* ok : {"1e400", "-1e400", "1e-400", "1e200/1e-200", "1e1000/1e999", "0e999999999999", "0/5"})
    BOOST_TEST(parse_exact_number(ok).has_value(), ok);
  BOOST_TEST(parse_exact_number(digits400).has_value());
  BOOST_TEST(parse_exact_number(digits1000 + "e-700").has_value());
  for (const char* beyond : {"1e401", "1.0000000001e400", "9e-401", "1e400/1e-1", "1e-300/1e300", "1e99999999999999999999999",
                             "1e-99999999999999999999999"})
    BOOST_TEST(problem(beyond).find("beyond the supported range") != std::string::npos, beyond);
  BOOST_TEST(problem(digits1000 + "7e-700").find("more than 1000 digits") != std::string::npos);
  // 1000 digits and in range (7.8e-400), but 7…7 / 10^1399 has a 1400-digit denominator
  BOOST_TEST(problem(digits1000 + "e-1399").find("lowest terms") != std::string::npos);
  BOOST_TEST(problem("3/0").find("zero denominator") != std::string::npos);
  BOOST_TEST(problem("0x10").find("not a finite number") != std::string::npos);
  BOOST_TEST(problem("  ") == "is empty");
  BOOST_TEST(problem("1/3").empty());
  // the value at the boundary is exact
  BOOST_TEST((*parse_exact_number("1e-400") * cln::expt_pos(cln::cl_I(10), 400U) == 1));
}

BOOST_AUTO_TEST_CASE(exact_text_of_every_accepted_value_reads_back) {
  // cln's p/q text of a value is accepted again: 1e400 prints with 401 digits, 7…7e-400 as 400/801 digits
  for (const std::string& text : {std::string("1e400"), std::string("-1e-400"), std::string(400, '7') + "e-400",
                                 std::string("1/3"), std::string("1e400/7"), std::string(1000, '9') + "e-700"}) {
    const auto x = parse_exact_number(text);
    BOOST_REQUIRE_MESSAGE(x.has_value(), text);
    std::ostringstream exact;
    exact << *x;
    const auto back = parse_exact_number(exact.str());
    BOOST_TEST((back && *back == *x), text);
  }
}

BOOST_AUTO_TEST_CASE(decimal_output_reads_back_within_half_a_unit) {
  // |to_decimal(x, d) − x| ≤ ½·10^(1−d)·|x| for values across the range, and exactly for short decimals
  for (const char* text : {"1/3", "-2/7", "10220/29376", "1e-400", "9.9999999999999999999e399", "123456789/1000", "-5e-7"})
    for (const int d : {1, 3, 17, 45}) {
      const cln::cl_RA x = *parse_exact_number(text);
      const auto y = parse_exact_number(to_decimal(x, d));
      BOOST_REQUIRE(y.has_value());
      // cln::expt_pos needs a positive exponent
      const cln::cl_I scale = d == 1 ? cln::cl_I(1) : cln::expt_pos(cln::cl_I(10), static_cast<unsigned>(d - 1));
      BOOST_TEST((2 * cln::abs(*y - x) * scale <= cln::abs(x)),
                 text << " at " << d << " digits");
    }
  BOOST_TEST((*parse_exact_number(to_decimal(cln::cl_RA(348) / 1000, 3)) == cln::cl_RA(348) / 1000));
  BOOST_CHECK_THROW(to_decimal(cln::cl_RA(1), 0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(refusals_are_one_printable_line) {
  for (const char* bad : {"1\n2,1,1", "1,\x01,1", "1e999,1,1", "1,2\r"}) {
    try {
      parse_moments(bad);
      BOOST_ERROR("accepted: " << bad);
    } catch (const std::invalid_argument& e) {
      const std::string m = e.what();
      BOOST_TEST(m.find_first_of("\n\r\x01") == std::string::npos, m);
    }
  }
  BOOST_TEST(printable_text("a\nb") == "a\\x0Ab");
  BOOST_TEST(std::string(parse_exact_number_checked("1e999").problem).find("range") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(decimal_output) {
  BOOST_TEST(to_decimal(cln::cl_RA(1) / 3, 5) == "3.3333e-1");
  BOOST_TEST(to_decimal(cln::cl_RA(-2), 3) == "-2.00");
  BOOST_TEST(to_decimal(cln::cl_RA(9999) / 1000, 2) == "1.0e1");
  BOOST_TEST(to_decimal(cln::cl_RA(0), 4) == "0");
}

BOOST_AUTO_TEST_CASE(bodies) {
  const auto water = parse_moments("water");
  BOOST_TEST((water.I[0] == cln::cl_RA(10220) / 29376));
  BOOST_TEST(symmetry_of(water).empty());
  BOOST_TEST(symmetry_of(parse_moments("sphere")) == "I1 = I2 = I3");
  BOOST_TEST(symmetry_of(parse_moments("1,1,3/2")) == "I1 = I2");
  BOOST_CHECK_THROW(parse_moments("0.345,0.653,1"), std::invalid_argument);  // Fassò's set violates eq. (77)
  BOOST_CHECK_THROW(parse_moments("0,1,1"), std::invalid_argument);
  BOOST_CHECK_THROW(parse_moments("-1,1,1"), std::invalid_argument);
  BOOST_CHECK_THROW(parse_moments("nan,1,1"), std::invalid_argument);
  BOOST_CHECK_THROW(parse_moments("1,1"), std::invalid_argument);
  BOOST_CHECK_THROW(parse_moments("1,1,1,1"), std::invalid_argument);
  BOOST_CHECK_NO_THROW(parse_moments("0.25,0.75,1"));  // the flat body: I1 + I2 = I3 is allowed
}

BOOST_AUTO_TEST_SUITE_END()  // exact_number_test
