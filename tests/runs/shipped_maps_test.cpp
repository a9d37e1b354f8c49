// The full-resolution maps shipped under data/maps-K200 (scripts/make-full-data.sh): each is a whole
// map of its family at --grid 200, and at bodies drawn at random from it the exact solver, run again
// here, gives the same best integrator, label, reference and ratio (runs/map_check). A family not
// shipped yet is skipped with a message.
#include <boost/test/unit_test.hpp>

#include <set>
#include <string>

#include "rotlie/runs/map_check.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/shipped_data.hpp"

using namespace rotlie;

BOOST_AUTO_TEST_SUITE(shipped_maps_test)

BOOST_AUTO_TEST_CASE(the_shipped_maps_are_whole_and_agree_with_the_exact_solver) {
  // bodies re-solved per family, within the slow suite's budget (a P body takes the exact solver about
  // 7 CPU s): the 200-body check of the screened P path at K = 200 is bench/map_check's, recorded in
  // data/README.md; N's continuation and R's exact solver were checked at every body of coarse grids
  const std::map<std::string, std::size_t> checks = {{"N", 100}, {"R", 20}, {"P", 20}};
  int shipped = 0;
  for (const auto& [family, count] : checks) {
    const auto file = runs::shipped_map(family);
    if (!file) {
      BOOST_TEST_MESSAGE("no shipped map of family " << family << " (data/maps-K200): skipped");
      continue;
    }
    ++shipped;
    BOOST_TEST_CONTEXT(file->string()) {
      const auto m = runs::read_map_contents(*file);
      BOOST_TEST_REQUIRE(m.has_value());
      BOOST_TEST(m->family == family);
      BOOST_TEST(m->K == 200);
      // every asymmetric body once: (K+1)^2 grid points less the symmetric tops
      std::set<std::pair<std::string, std::string>> places;
      for (const auto& b : m->bodies) places.emplace(b.at("s").get<std::string>(), b.at("t").get<std::string>());
      BOOST_TEST(places.size() == m->bodies.size());
      BOOST_TEST(m->bodies.size() == 39800u);
      const auto r = runs::check_map_lines(family, m->K, m->bodies, count, 2026);
      BOOST_TEST(r.checked == static_cast<int>(count));
      BOOST_TEST(r.disagreements == 0);
      for (const auto& d : r.differences) BOOST_TEST_MESSAGE(d);
    }
  }
  BOOST_TEST(shipped >= 1, "no shipped map found at all");
}

BOOST_AUTO_TEST_SUITE_END()  // shipped_maps_test
