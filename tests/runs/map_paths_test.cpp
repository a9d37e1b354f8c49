// Which path a map takes at which grid: the screened P path only where it was checked against the
// exact solver (K ≥ 200); at coarser grids the exact solver (map_p_cli_test checks it against solve).
#include <boost/test/unit_test.hpp>

#include "rotlie/bch/families.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/user_input.hpp"

using namespace rotlie;

BOOST_AUTO_TEST_SUITE(map_paths_test)

BOOST_AUTO_TEST_CASE(the_screened_path_only_at_the_grids_where_it_was_checked) {
  const auto& P = runs::family_to_map("P");
  BOOST_TEST((runs::map_method_asked(P, 200, false, false) == bch::map_method::screened));
  BOOST_TEST((runs::map_method_asked(P, 400, false, true) == bch::map_method::screened));
  for (const int K : {2, 3, 5, 8, 40, 199}) BOOST_TEST((runs::map_method_asked(P, K, false, false) == bch::map_method::exact), "K = " << K);
  BOOST_CHECK_THROW(runs::map_method_asked(P, 8, false, true), runs::bad_input);
  // N's continuation agreed with the exact solver at every body of grids 3 to 10 and 20
  const auto& N = runs::family_to_map("N");
  for (const int K : {3, 8, 40, 200}) BOOST_TEST((runs::map_method_asked(N, K, false, false) == bch::map_method::fast));
  BOOST_TEST((runs::map_method_asked(N, 8, true, false) == bch::map_method::exact));
}

BOOST_AUTO_TEST_SUITE_END()  // map_paths_test
