// `rotlie binary` with an ICQ shape model (Gaskell's format) as the primary: the run works and its
// mass and end state are near those of the ellipsoid the model approximates; a truncated ICQ file is
// refused in one line with exit status 2, nothing on stdout.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "icq_ellipsoid.hpp"

BOOST_AUTO_TEST_SUITE(binary_icq_cli_test)

using namespace rotlie::test_cli;

namespace {

// The Didymos system's primary ellipsoid (km) and its run, with the primary replaced.
constexpr double a = 0.39888, b = 0.39130, c = 0.38348;
const std::string rest = " --secondary ellipsoid:0.10316,0.07935,0.06613 --separation 1.2 --integrator KEPLER2 --h 60 --T 3600 --order 2 --json";

fs::path icq_file(int q, bool truncated = false) {
  auto text = rotlie::test_support::icq_ellipsoid_text(q, a, b, c);
  if (truncated) text.resize(text.size() / 2);
  const fs::path p = scratch() / ("primary-" + std::to_string(q) + (truncated ? "-cut" : "") + ".icq");
  std::ofstream(p) << text;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(an_icq_primary_runs_as_the_ellipsoid_it_approximates) {
  const auto icq = run("binary --primary polyhedron:" + icq_file(32).string() + " --density 2203" + rest);
  BOOST_TEST_REQUIRE(icq.status == 0, icq.err);
  const auto x = nlohmann::json::parse(icq.out);
  const std::string ellipsoid = "ellipsoid:" + std::to_string(a) + "," + std::to_string(b) + "," + std::to_string(c);
  const auto same_density = nlohmann::json::parse(run("binary --primary " + ellipsoid + " --density 2203" + rest).out);
  // at Q = 32 the inscribed mesh lacks about 1.6e-3 of the ellipsoid's volume
  const double m1 = x["masses"][0].get<double>(), m2 = same_density["masses"][0].get<double>();
  BOOST_TEST(m1 < m2);
  BOOST_TEST(m1 > m2 * (1 - 3e-3), m1 << " against " << m2);
  // of the same masses, the two primaries differ only in shape: the orbits agree closely
  std::ostringstream masses;
  masses.precision(17);
  masses << " --mass " << m1 << "," << x["masses"][1].get<double>();
  const auto y = run("binary --primary " + ellipsoid + masses.str() + rest);
  BOOST_TEST_REQUIRE(y.status == 0, y.err);
  const auto same_mass = nlohmann::json::parse(y.out);
  double apart = 0;
  for (int k = 0; k < 3; ++k) apart = std::max(apart, std::abs(x["r"][k].get<double>() - same_mass["r"][k].get<double>()));
  BOOST_TEST_MESSAGE("end positions " << apart << " km apart");
  BOOST_TEST(apart < 1e-5, "the end positions differ by " << apart << " km");
  BOOST_TEST(x["max_rel_energy_error"].get<double>() < 1e-8);
}

BOOST_AUTO_TEST_CASE(a_truncated_icq_file_is_refused_in_one_line) {
  const auto r = run("binary --primary polyhedron:" + icq_file(8, true).string() + " --density 2203" + rest);
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(r.out.empty());
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.err.find("--primary") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("an ICQ model of Q = 8 has 6(Q+1)^2 = 486 vertex lines") != std::string::npos, r.err);
}

BOOST_AUTO_TEST_SUITE_END()
