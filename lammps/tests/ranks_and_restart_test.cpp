#include <boost/test/unit_test.hpp>
BOOST_AUTO_TEST_SUITE(ranks_and_restart_test)
BOOST_AUTO_TEST_CASE(placeholder) {}
BOOST_AUTO_TEST_SUITE_END()
