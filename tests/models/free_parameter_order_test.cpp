// Order tests for the free-parameter families (slow: the P family takes a minute to solve): every
// real critical point of R and P1-P15 the solver produces for water, run as a scheme table, has a
// fitted slope of 4 within 0.1. The fit uses five step levels starting where h·max|c| ≤ 1/8 (and at
// h = 2^-6 at the latest): some critical points have coefficients in the hundreds (P5 ACB (1) has
// a1 ≈ −287), and their error reaches the h⁴ regime only at correspondingly smaller steps.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "model_support.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

BOOST_AUTO_TEST_SUITE(free_parameter_order_test)

using namespace rotlie;

namespace {

double slope(const schemes::scheme_table& t, const models::vec3<long double>& I, int first, int last) {
  return models::measure_order<long double>(t, I, test::initial_state<long double>({1, 1, 1}), 1.0L, first, last,
                                            last - first + 1)
      .slope;
}

void check_family(const std::vector<std::string>& schemes, std::size_t expected) {
  const auto body = lie::parse_moments("water");
  const auto water = test::water_moments<long double>();
  const auto r = solver::solve_dedicated(body, schemes, bch::permutation_names(), 40);
  BOOST_TEST(r.solutions.size() == expected);
  int delayed = 0;
  for (const auto& s : r.solutions) {
    const auto t = schemes::parse_scheme_table(solver::scheme_table_text(s, body, 40));
    double largest = 0;
    for (const auto& st : t.stages) largest = std::max(largest, std::abs(std::stod(st.value)));
    const int first = std::max(6, static_cast<int>(std::ceil(std::log2(8 * largest))));
    delayed += first > 6;
    const double p = slope(t, water, first, first + 4);
    BOOST_TEST(std::abs(p - 4) < 0.1, s.name() << " slope " << p << " over h = 2^-" << first << " … 2^-" << first + 4);
  }
  BOOST_TEST_MESSAGE(r.solutions.size() << " schemes, " << delayed << " fitted beyond h = 2^-6 for their large coefficients");
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_r_solution_for_water_is_fourth_order) { check_family({"R"}, 46); }  // the paper counts 46 (section 4.3)

BOOST_AUTO_TEST_CASE(every_p_solution_for_water_is_fourth_order) {
  std::vector<std::string> p;
  for (int i = 1; i <= 15; ++i) p.push_back("P" + std::to_string(i));
  check_family(p, 724);  // the paper counts 724 (section 4.3)
}

BOOST_AUTO_TEST_SUITE_END()  // free_parameter_order_test
