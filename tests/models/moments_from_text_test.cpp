// The body's moments read from exact text into each scalar: a rational p/q lands on the nearest
// value of the scalar itself (float128 runs never see double's rounding), decimals likewise, very
// long integers that overflow the scalar still give their quotient, and bad text is refused.
#include <boost/test/unit_test.hpp>

#include "model_support.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/schemes/same_body.hpp"

BOOST_AUTO_TEST_SUITE(moments_from_text_test)

using namespace rotlie;
using rotlie::quad;

namespace {
const std::string water = "10220/29376 19187/29376 1";
// 10220/29376 = 2555/7344 and 19187/29376 to 70 digits (long division), read by the scalar's own
// correctly rounded decimal conversion: an independent route to the nearest value.
const char* water_1 = "0.3479030501089324618736383442265795206971677559912854030501089324618736";
const char* water_2 = "0.6531522331154684095860566448801742919389978213507625272331154684095861";
}  // namespace

BOOST_AUTO_TEST_CASE(float128_moments_are_the_rationals_rounded_to_float128) {
  const auto I = models::moments_from_text<quad>(water);
  BOOST_TEST((I[0] == quad(water_1)));
  BOOST_TEST((I[1] == quad(water_2)));
  BOOST_TEST((I[2] == quad(1)));
  // not the double value widened: that one is about 1e-17 away, 1e17 float128 ulps
  const quad via_double(10220.0 / 29376.0);
  BOOST_TEST((I[0] != via_double));
  BOOST_TEST(static_cast<double>(abs(I[0] - via_double)) > 1e-19);
  BOOST_TEST(static_cast<double>(abs(I[0] - quad(water_1))) == 0.0);
}

BOOST_AUTO_TEST_CASE(double_and_long_double_moments_are_the_rationals_rounded_once) {
  const auto d = models::moments_from_text<double>(water);
  BOOST_TEST(d[0] == std::strtod(water_1, nullptr));
  BOOST_TEST(d[1] == std::strtod(water_2, nullptr));
  const auto l = models::moments_from_text<long double>(water);
  BOOST_TEST(l[0] == std::strtold(water_1, nullptr));
  BOOST_TEST(l[1] == std::strtold(water_2, nullptr));
  BOOST_TEST((l[0] != static_cast<long double>(d[0])));
}

BOOST_AUTO_TEST_CASE(decimals_and_scaled_forms_read_exactly) {
  // 0.348 is not a binary fraction: float128 must hold the float128 nearest, not double's
  const auto I = models::moments_from_text<quad>("3.48e-1 +0.652 1.0");
  BOOST_TEST((I[0] == quad("0.348")));
  BOOST_TEST((I[0] != quad(0.348)));
  BOOST_TEST((I[1] == quad("0.652")));
  BOOST_TEST((I[2] == quad(1)));
  const auto d = models::moments_from_text<double>("348/1000 0.652 00001");
  BOOST_TEST(d[0] == 0.348);
  BOOST_TEST(d[2] == 1.0);
  // decimals in both parts of a quotient: (1.5/3) = 0.5 exactly
  BOOST_TEST(models::moment_from_text<double>("1.5/3") == 0.5);
}

BOOST_AUTO_TEST_CASE(parts_beyond_the_scalar_range_still_give_their_quotient) {
  // p and q overflow double (and 1e-400 underflows it); their quotients do not
  const auto d = models::moments_from_text<double>("1e400/1e400 3e400/2e400 1e-400/1e-400");
  BOOST_TEST(d[0] == 1.0);
  BOOST_TEST(d[1] == 1.5);
  BOOST_TEST(d[2] == 1.0);
  const std::string big(350, '9');  // 10^350 − 1
  BOOST_TEST(std::abs(models::moment_from_text<double>(big + "/1" + std::string(350, '0')) - 1) < 1e-15);
}

BOOST_AUTO_TEST_CASE(bad_text_is_refused) {
  for (const char* bad : {"", "1 1", "1 1 1 1", "a 1 1", "-1 1 1", "0 1 1", "0/1 1 1", "1/0 1 1", "nan 1 1", "inf 1 1",
                          "0x1p3 1 1", "1e 1 1", "1/2/3 1 1", "1e401 1 1", "1,1,1", "1 1 3"})
    BOOST_CHECK_THROW(models::moments_from_text<double>(bad), std::invalid_argument);
  BOOST_CHECK_THROW(models::moments_from_text<double>("1e300/1e-300 1 1"), std::invalid_argument);  // 1e600: out of range
}

BOOST_AUTO_TEST_CASE(the_reader_accepts_exactly_what_the_table_body_comparison_accepts) {
  // one scanner for both: a moment is read iff schemes::same_body can compare it (values inside the
  // scalar's range: the range check is the reader's own)
  const std::string zeros_401 = "0." + std::string(399, '0') + "1";  // 401 digits written: beyond the limit
  const std::string zeros_400 = "0." + std::string(398, '0') + "1";
  for (const std::string& x : {std::string("1"), std::string("0.5e3"), std::string("1e400/1e400"), std::string("1e401"), zeros_400,
                               zeros_401, std::string("+7/3"), std::string("2/0"), std::string(".5"), std::string("5.")}) {
    bool read = true, compared = true;
    try {
      models::moment_from_text<long double>(x);
    } catch (const std::invalid_argument&) {
      read = false;
    }
    try {
      schemes::scheme_table t;
      t.inertia = x + " " + x + " " + x;
      schemes::same_body(t, {x, x, x});
    } catch (const std::invalid_argument&) {
      compared = false;
    }
    BOOST_TEST(read == compared, x.substr(0, 12) << "… (" << x.size() << " characters)");
  }
}

BOOST_AUTO_TEST_SUITE_END()  // moments_from_text_test
