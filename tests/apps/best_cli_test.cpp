// rotlie best's measured column end to end at water: every field (old and new) is there, each
// measured best is the smallest error among its candidates, and the measured errors agree with a
// second, independent run of the protocol (`rotlie order` in long double at a dyadic step, brought
// to h/C = 1/1980 by the h^4 law) — both the ordering and the size. About 25 s: slow.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

BOOST_AUTO_TEST_SUITE(best_cli_test)

namespace fs = std::filesystem;

using namespace rotlie::test_cli;

namespace {

const nlohmann::json& water() {
  static const nlohmann::json j = [] {
    const auto r = run("best --inertia water --json");
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    return nlohmann::json::parse(r.out);
  }();
  return j;
}

// The long-double protocol's mean attitude error of `scheme` at h = 2^-7, brought to h/C = 1/1980
// by (h/C)^4 (every scheme here is of order 4 and in its h^4 regime at this step).
double second_protocol_error(const std::string& scheme, int cost) {
  const auto r = run("order --scheme " + scheme + " --inertia water --scalar long-double --min-level 5 --max-level 7 --json");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& p : j.at("points"))
    if (p.at("h").get<double>() == 1.0 / 128) return p.at("error").get<double>() * std::pow(128.0 * cost / 1980.0, 4);
  BOOST_FAIL("no point at h = 1/128");
  return 0;
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_field_is_there) {
  const auto& j = water();
  for (const auto* key : {"inertia", "s", "t", "N", "R", "P", "reference", "recommended", "measure", "reference_measured",
                          "best_reference_measured", "references_measured", "recommended_measured", "measured_protocol",
                          "cpu_seconds"})
    BOOST_TEST(j.contains(key), key);
  for (const auto* f : {"N", "R", "P"}) {
    for (const auto* key : {"best", "remainder", "cost", "gain", "singular", "measured"}) BOOST_TEST(j.at(f).contains(key));
    for (const auto* key : {"best", "error", "gain", "analytic_best_error", "analytic_best_gain", "candidates"})
      BOOST_TEST(j.at(f).at("measured").contains(key));
  }
  BOOST_TEST(j.at("references_measured").size() == 12u);
  BOOST_TEST_MESSAGE("best --inertia water: " << j.at("cpu_seconds").get<double>() << " s CPU");
}

BOOST_AUTO_TEST_CASE(each_measured_best_is_the_smallest_measured_error) {
  const auto& j = water();
  for (const auto* f : {"N", "R", "P"}) {
    const auto& m = j.at(f).at("measured");
    BOOST_TEST_REQUIRE(!m.at("candidates").empty());
    double smallest = INFINITY;
    std::string name;
    for (const auto& c : m.at("candidates"))
      if (c.at("error").get<double>() < smallest) smallest = c.at("error").get<double>(), name = c.at("name").get<std::string>();
    BOOST_TEST(m.at("best").get<std::string>() == name);
    BOOST_TEST(m.at("error").get<double>() == smallest);
    // the gain is the measured RS4 S5 McLachlan error over this one
    BOOST_TEST(std::abs(m.at("gain").get<double>() * smallest / j.at("reference_measured").at("error").get<double>() - 1) < 1e-12);
  }
  double smallest = INFINITY;
  for (const auto& r : j.at("references_measured")) smallest = std::min(smallest, r.at("error").get<double>());
  BOOST_TEST(j.at("best_reference_measured").at("error").get<double>() == smallest);
}

// The second protocol: another integrator loop (long double, dyadic steps, samples of the exact
// flow) must confirm the measured best against the analytic best, and each error within 3 %.
BOOST_AUTO_TEST_CASE(a_second_run_of_the_protocol_confirms_the_measured_errors) {
  const auto& j = water();
  const auto& p = j.at("P").at("measured");
  const std::string measured_best = p.at("best"), analytic_best = j.at("P").at("best");
  BOOST_TEST_REQUIRE(measured_best != analytic_best);  // the maps' known failure at water (issue 14)
  const double e_measured = second_protocol_error(measured_best, 11), e_analytic = second_protocol_error(analytic_best, 11);
  BOOST_TEST(e_measured < e_analytic);
  BOOST_TEST(std::abs(e_measured / p.at("error").get<double>() - 1) < 0.03);
  BOOST_TEST(std::abs(e_analytic / p.at("analytic_best_error").get<double>() - 1) < 0.03);
  const auto& n = j.at("N").at("measured");
  BOOST_TEST(std::abs(second_protocol_error(n.at("best"), 9) / n.at("error").get<double>() - 1) < 0.03);
  const auto& rs4 = j.at("reference_measured");
  BOOST_TEST(std::abs(second_protocol_error(rs4.at("best"), 12) / rs4.at("error").get<double>() - 1) < 0.03);
}

BOOST_AUTO_TEST_CASE(analytic_only_and_bad_input) {
  const auto r = run("best --inertia water --json --analytic-only");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  BOOST_TEST(!j.contains("reference_measured"));
  BOOST_TEST(!j.at("P").contains("measured"));
  BOOST_TEST(j.at("P").at("best") == water().at("P").at("best"));
  for (const auto* args : {"best --analytic-only --inertia 1,2,4", "best --inertia 1/2,1/2,1", "best --inertia 0,1,1 --json"}) {
    const auto bad = run(args);
    BOOST_TEST(bad.status == 2, args);
    BOOST_TEST(bad.err.rfind("rotlie: error: ", 0) == 0u, args << ": " << bad.err);
    BOOST_TEST(std::count(bad.err.begin(), bad.err.end(), '\n') == 1, args);
    BOOST_TEST(bad.out.empty(), args);
  }
}

BOOST_AUTO_TEST_SUITE_END()  // best_cli_test
