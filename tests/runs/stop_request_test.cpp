// Stopping long symbolic work from another thread (lie/stop_request.hpp, used by Python's Ctrl-C):
// a stop point throws only inside a scope whose flag is set; the solver, the BCH engine and the map
// rows stop at their points, and a stop is never written down as a failed result.
#include <boost/test/unit_test.hpp>

#include <atomic>
#include <exception>
#include <thread>
#include <type_traits>

#include "rotlie/bch/families.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/map_rows.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

using namespace rotlie;

BOOST_AUTO_TEST_SUITE(stop_request_test)

BOOST_AUTO_TEST_CASE(a_stop_point_throws_only_inside_a_scope_whose_flag_is_set) {
  BOOST_CHECK_NO_THROW(lie::stop_point());
  std::atomic<bool> outer{false}, inner{true};
  {
    const lie::stop_scope a(outer);
    BOOST_CHECK_NO_THROW(lie::stop_point());
    {
      const lie::stop_scope b(inner);
      BOOST_CHECK_THROW(lie::stop_point(), lie::stopped);
    }
    BOOST_CHECK_NO_THROW(lie::stop_point());  // the outer scope is back
    outer = true;
    BOOST_CHECK_THROW(lie::stop_point(), lie::stopped);
  }
  BOOST_CHECK_NO_THROW(lie::stop_point());
  // the scope is the thread's own: another thread is not stopped by it
  const std::atomic<bool> set{true};
  const lie::stop_scope here(set);
  bool other_threw = false;
  std::thread([&] {
    try {
      lie::stop_point();
    } catch (const lie::stopped&) {
      other_threw = true;
    }
  }).join();
  BOOST_TEST(!other_threw);
}

BOOST_AUTO_TEST_CASE(the_solver_and_the_bch_engine_stop_at_their_points) {
  const std::atomic<bool> set{true};
  const lie::stop_scope scope(set);
  const lie::moments_of_inertia water{cln::cl_RA(2555) / 7344, cln::cl_RA(19187) / 29376, cln::cl_RA(1)};
  BOOST_CHECK_THROW(solver::solve_dedicated(water, {"N2"}, {"ABC"}, 40), lie::stopped);
  bch::remainder_request r;
  r.scheme = "ABCBA";
  r.order = 3;
  BOOST_CHECK_THROW(bch::compute_remainder(r), lie::stopped);
}

// The places that write a failure down (map_rows' body_line, the row path's fallback) catch
// std::exception: a stop must pass through them.
static_assert(!std::is_base_of_v<std::exception, lie::stopped>);

BOOST_AUTO_TEST_CASE(a_stopped_map_row_is_not_written_as_failed_bodies) {
  const auto bodies = solver::asymmetric_grid(4);
  const std::vector<char> done(bodies.size(), 0);
  const std::atomic<bool> set{true};
  const lie::stop_scope scope(set);
  for (const auto method : {bch::map_method::exact, bch::map_method::fast})
    BOOST_CHECK_THROW(runs::map_row_lines(bodies, 0, 2, done, "N", method), lie::stopped);
}

BOOST_AUTO_TEST_SUITE_END()  // stop_request_test
