// `rotlie solve` end to end for a body given in another unit: the JSON (but for the body as given
// and the timings) and every table written with --out (but for the inertia line) are those of the
// body scaled to I3 = 1, and nothing in them is NaN or null.
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

BOOST_AUTO_TEST_SUITE(solve_scale_cli_test)

namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  static const fs::path dir = fs::temp_directory_path() / ("rotlie-solve-scale-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// stdout of `rotlie args`; the test fails on a non-zero status.
std::string rotlie(const std::string& args) {
  const fs::path out = scratch() / "stdout";
  const std::string cmd = std::string(ROTLIE_BINARY) + " " + args + " >" + out.string() + " 2>/dev/null </dev/null";
  const int raw = std::system(cmd.c_str());
  BOOST_TEST_REQUIRE((WIFEXITED(raw) && WEXITSTATUS(raw) == 0), "rotlie " << args << " failed");
  return slurp(out);
}

// NaN or inf as printf writes them, or JSON's null for a non-finite double.
const std::regex& not_a_number() {
  static const std::regex r("(^|[^a-z])(nan|inf|null)([^a-z]|$)", std::regex::icase);
  return r;
}

nlohmann::json without_body_and_timings(nlohmann::json j) {
  j.erase("inertia");
  j.erase("seconds");
  return j;
}

// Water's moments times 10^k, in the text a user would type.
std::string water_times(int k) {
  const std::string e = "e" + std::to_string(k);
  return "2555" + e + "/7344,19187" + e + "/29376,1" + e;
}

}  // namespace

BOOST_AUTO_TEST_CASE(solve_json_and_tables_for_a_scaled_body_equal_the_unit_body) {
  const fs::path unit_dir = scratch() / "unit";
  const auto unit = nlohmann::json::parse(rotlie("solve --family N --inertia water --json --out " + unit_dir.string()));
  BOOST_TEST(unit.at("real_solutions").get<int>() == 90);
  BOOST_TEST(!std::regex_search(unit.dump(), not_a_number()));
  for (int k : {-100, 20, 40, 100, 150}) {
    BOOST_TEST_CONTEXT("water x 1e" << k) {
      const fs::path dir = scratch() / ("x" + std::to_string(k));
      const std::string text = rotlie("solve --family N --inertia " + water_times(k) + " --json --out " + dir.string());
      BOOST_TEST(!std::regex_search(text, not_a_number()));
      const auto scaled = nlohmann::json::parse(text);
      BOOST_TEST(scaled.at("real_solutions").get<int>() == 90);
      BOOST_TEST((without_body_and_timings(scaled) == without_body_and_timings(unit)));
      std::size_t tables = 0;
      for (const auto& entry : fs::directory_iterator(unit_dir)) {
        const std::string a = slurp(entry.path()), b = slurp(dir / entry.path().filename());
        const std::regex inertia("\ninertia [^\n]*\n");
        BOOST_TEST(std::regex_replace(a, inertia, "\n") == std::regex_replace(b, inertia, "\n"), entry.path().filename());
        BOOST_TEST(b.find("\norder 4\n") != std::string::npos);
        ++tables;
      }
      BOOST_TEST(tables == 90u);
    }
  }
  // the plain text ranks the same, no NaN
  const std::string ranked = rotlie("solve --family N --inertia " + water_times(150));
  BOOST_TEST(!std::regex_search(ranked, not_a_number()));
  BOOST_TEST(ranked.find("N2 BAC (2)") != std::string::npos);
  fs::remove_all(scratch());
}

BOOST_AUTO_TEST_CASE(remainder_json_values_of_a_scaled_body_follow_homogeneity) {
  // H_Rk is homogeneous of degree −k in the moments: at scale 10^s each coefficient is the unit
  // body's times 10^(−k·s). Beyond a double's range the value is a decimal string, never null or 0.
  const std::string coeffs =
      " --coeffs a1=4.550462477459105042901927628113604130174e-2,a2=1.520832836133472662135329443017579676715e-1 --order 5 --json";
  const auto unit = nlohmann::json::parse(rotlie("remainder --scheme N2 --perm BAC --inertia water" + coeffs));
  for (int s : {-100, 100}) {
    const std::string text = rotlie("remainder --scheme N2 --perm BAC --inertia " + water_times(s) + coeffs);
    BOOST_TEST(!std::regex_search(text, not_a_number()));
    const auto scaled = nlohmann::json::parse(text);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < unit.at("orders").size(); ++i) {
      const int k = unit["orders"][i]["order"].get<int>();
      const auto& a = unit["orders"][i]["terms"];
      const auto& b = scaled["orders"][i]["terms"];
      BOOST_REQUIRE(a.size() == b.size());
      for (std::size_t t = 0; t < a.size(); ++t) {
        const double want_mantissa = a[t]["value"].get<double>();
        const auto& got = b[t]["value"];
        // got = want × 10^(−k·s): compare the mantissa, from the number or the decimal string
        const double got_value = got.is_string() ? std::stod(std::regex_replace(got.get<std::string>(), std::regex("e-?[0-9]+$"), "")) *
                                                       std::pow(10.0, std::stoi(std::regex_replace(got.get<std::string>(), std::regex("^[^e]*e"), "")) + k * s)
                                                 : got.get<double>() * std::pow(10.0, k * s);
        BOOST_TEST(got_value == want_mantissa, boost::test_tools::tolerance(1e-12));
        ++checked;
      }
    }
    BOOST_TEST(checked >= 10u);  // H_R3 and H_R5 of N2 BAC: 3 + 7 terms
  }
}

BOOST_AUTO_TEST_SUITE_END()  // solve_scale_cli_test
