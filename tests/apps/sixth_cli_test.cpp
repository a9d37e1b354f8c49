// `rotlie sixth` end to end: bad input is one line and exit status 2; a search of one system writes a
// resumable state (a second run spends no new starts and finds the same roots) and an order-6 table
// that `integrate --scheme FILE` accepts for the same body; --references lists the general compositions.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(sixth_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

BOOST_AUTO_TEST_CASE(bad_input_is_one_line_and_status_two) {
  for (const char* args : {"sixth", "sixth --inertia water", "sixth --inertia water --all --words ABABABACABCBACABABABA",
                           "sixth --inertia water --words ABC", "sixth --inertia water --words ABABABACABCBACABABABA:XYZ",
                           "sixth --inertia foo --all", "sixth --inertia water --all --starts 0",
                           "sixth --inertia water --all --starts -3", "sixth --inertia water --all --digits 12",
                           "sixth --inertia water --all --split XY", "sixth --inertia 1,2 --all"}) {
    const auto r = run(args);
    BOOST_TEST(r.status == 2, args << ": " << r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, args << ": " << r.err);
    BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0, args << ": " << r.err);
    BOOST_TEST(r.out.empty(), args);
  }
}

BOOST_AUTO_TEST_CASE(a_search_resumes_and_writes_a_table_that_integrate_accepts) {
  const fs::path out = scratch() / "search";
  const std::string args = "sixth --inertia water --words ABABABACABCBACABABABA:BCA --starts 200 --best 1 --json --out " + out.string();
  const auto first = run(args);
  BOOST_TEST_REQUIRE(first.status == 0, first.err);
  const auto j = nlohmann::json::parse(first.out);
  BOOST_TEST(j["systems"].get<int>() == 1);
  BOOST_TEST(j["starts"].get<int>() == 200);
  BOOST_TEST_REQUIRE(j["roots"].get<int>() >= 1);
  BOOST_TEST(j["best"][0]["residual"].get<double>() < 1e-40);
  const std::string file = j["best"][0]["file"];
  BOOST_TEST_REQUIRE(fs::exists(file));
  BOOST_TEST(slurp(file).find("order 6\n") != std::string::npos);
  // Resumed: the state already holds the 200 starts, so the same roots come back without new work.
  const auto second = run(args);
  BOOST_TEST_REQUIRE(second.status == 0, second.err);
  const auto k = nlohmann::json::parse(second.out);
  BOOST_TEST(k["starts"] == j["starts"]);
  BOOST_TEST(k["roots"] == j["roots"]);
  BOOST_TEST(k["best"][0]["remainder7"] == j["best"][0]["remainder7"]);
  const auto integrated = run("integrate --scheme " + file + " --inertia water --h 0.01 --json");
  BOOST_TEST(integrated.status == 0, integrated.err);
  const auto other = run("integrate --scheme " + file + " --inertia 1,2,3 --h 0.01");
  BOOST_TEST(other.status != 0);  // a table solved for water, refused for another body without --force
  fs::remove_all(scratch() / "search");
}

BOOST_AUTO_TEST_CASE(references_are_listed) {
  const auto r = run("sixth --references --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(j.size() == 8u);
  for (const auto& e : j) BOOST_TEST(e["order"].get<int>() == 6);
}

BOOST_AUTO_TEST_SUITE_END()  // sixth_cli_test
