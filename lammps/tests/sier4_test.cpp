#include <boost/test/unit_test.hpp>
BOOST_AUTO_TEST_SUITE(sier4_test)
BOOST_AUTO_TEST_CASE(placeholder) {}
BOOST_AUTO_TEST_SUITE_END()
