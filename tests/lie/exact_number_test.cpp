// Exact numbers from text and rigid-body moments: parsing, refusals, eq. (77).
#define BOOST_TEST_MODULE exact_number
#include <boost/test/unit_test.hpp>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/rigid_body.hpp"

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
