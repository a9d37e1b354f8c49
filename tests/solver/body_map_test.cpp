// The grid of LV section 5.1 (exact, 40,401 points at K = 200, symmetric tops skipped, flat bodies
// kept) and the map point: the reference remainder by a second method (the exact symbolic
// expansion), the best of each permutation against every solution of the exact solver, the costs of
// section 4.1 and the equal-cost ratio.
#include <boost/test/unit_test.hpp>

#include <cln/float.h>
#include <cln/real.h>
#include <ginac/ginac.h>

#include <cmath>
#include <set>

#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

BOOST_AUTO_TEST_SUITE(body_map_test)

using namespace rotlie;
using cln::cl_RA;

BOOST_AUTO_TEST_CASE(the_paper_grid_has_40401_points_and_39800_asymmetric_bodies) {
  const auto all = solver::body_grid(200);
  BOOST_TEST(all.size() == 40401u);
  const auto asymmetric = solver::asymmetric_grid(200);
  // s = 0 is the flat symmetric top (1/2, 1/2, 1) for every t, s = 1 the edge I2 = I3, t = 1 the edge I1 = I2.
  BOOST_TEST(asymmetric.size() == 199u * 200u);
  std::set<std::pair<int, int>> seen;
  for (const auto& g : all) seen.insert({g.i, g.j});
  BOOST_TEST(seen.size() == 40401u);
}

BOOST_AUTO_TEST_CASE(every_grid_point_is_the_stated_exact_body) {
  const int K = 40;
  for (const auto& g : solver::body_grid(K)) {
    BOOST_TEST((g.s * K == g.i));
    BOOST_TEST((g.t * K == g.j));
    const cl_RA I2 = cl_RA(1) / 2 + g.s / 2, I1 = (1 - I2) + g.t * (2 * I2 - 1);
    BOOST_TEST((g.body.I[0] == I1 && g.body.I[1] == I2 && g.body.I[2] == 1));
    // The triangle I1 ≤ I2 ≤ 1, I1 + I2 ≥ 1 (eq. 77 with I3 the largest).
    BOOST_TEST((I1 <= I2 && I2 <= 1 && I1 + I2 >= 1));
    BOOST_TEST(g.symmetric == (g.i == 0 || g.i == K || g.j == K));
    BOOST_TEST(g.flat == (g.j == 0 || g.i == 0));
    if (!g.symmetric) {
      const auto [s, t] = solver::triangle_coordinates(g.body);
      BOOST_TEST((s == g.s && t == g.t));
      // The same body in another unit and order of axes has the same place in the triangle.
      const lie::moments_of_inertia other{{g.body.I[1] * 7, g.body.I[2] * 7, g.body.I[0] * 7}};
      BOOST_TEST((solver::triangle_coordinates(other) == std::pair<cl_RA, cl_RA>(g.s, g.t)));
    }
  }
}

BOOST_AUTO_TEST_CASE(grid_sizes_out_of_range_are_refused) {
  BOOST_CHECK_THROW(solver::body_grid(0), std::invalid_argument);
  BOOST_CHECK_THROW(solver::body_grid(-3), std::invalid_argument);
  BOOST_CHECK_THROW(solver::body_grid(static_cast<int>(solver::max_grid_divisions) + 1), std::invalid_argument);
  BOOST_CHECK_THROW(solver::triangle_coordinates(lie::parse_moments("1,1,2")), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(costs_are_those_of_section_4_1) {
  BOOST_TEST(solver::family_cost("N") == 9);
  BOOST_TEST(solver::family_cost("R") == 10);
  BOOST_TEST(solver::family_cost("P") == 11);
  BOOST_TEST(solver::reference_cost(solver::map_reference_scheme) == 12);
  BOOST_CHECK_THROW(solver::family_schemes("Q"), std::invalid_argument);
}

// RS4 S5 McLachlan's x1 y1 x2 y2 x3 y3 …: x1 = (14 − √19)/108, x2 = (20 − 7√19)/108, y1 = y3 = 2/5,
// y2 = −1/10, as rationals within 10^-35, and H_R5 expanded exactly (GiNaC) at those values.
double reference_remainder_exactly(const lie::moments_of_inertia& body, const std::string& perm) {
  const cln::cl_F root19 = cln::sqrt(cln::cl_float(19, cln::float_format(50)));
  const cl_RA x1 = cln::rational((14 - root19) / 108), x2 = cln::rational((20 - 7 * root19) / 108);
  const std::vector<cl_RA> stages = {x1, cl_RA(2) / 5, x2, cl_RA(-1) / 10, cl_RA(1) / 2 - x1 - x2, cl_RA(2) / 5};
  const std::string word = "RSRSRSRSRSR";
  const auto layout = bch::layout_scheme(word, bch::splitting::rs, perm);
  bch::remainder_request request;
  request.scheme = word;
  request.split = bch::splitting::rs;
  request.permutation = perm;
  request.order = 5;
  const cl_RA scale = body.I[2];
  request.inertia = lie::moments_of_inertia{{body.I[0] / scale, body.I[1] / scale, cl_RA(1)}};
  for (const auto& name : layout.free_coefficients)
    for (std::size_t k = 0; k < 6; ++k)
      if (layout.stages[k].coefficient == name) request.coefficients.emplace_back(name, stages[k]);
  const auto r = bch::compute_remainder(request);
  double sum = 0;
  for (const auto& [m, c] : r.k.remainder[5].terms()) {
    const double v = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(c)).to_double();
    sum += v * v;
  }
  return std::sqrt(sum);
}

BOOST_AUTO_TEST_CASE(reference_remainder_agrees_with_the_exact_expansion) {
  for (const auto& text : {"water", "3/8,5/8,1", "7/10,9/10,1"}) {
    const auto body = lie::parse_moments(text);
    for (const auto& perm : bch::permutation_names()) {
      const double fast = solver::reference_analytic_remainder(body, solver::map_reference_scheme, perm);
      const double exact = reference_remainder_exactly(body, perm);
      BOOST_TEST(fast == exact, boost::test_tools::tolerance(1e-11));
    }
  }
}

BOOST_AUTO_TEST_CASE(map_point_best_is_the_least_remainder_of_each_permutation) {
  const auto body = lie::parse_moments("7/16,5/8,1");
  const auto solved = solver::solve_dedicated(body, solver::family_schemes("N"), bch::permutation_names(), 40);
  const auto p = solver::summarize_family(body, "N", solved);
  BOOST_REQUIRE(p.best);
  BOOST_REQUIRE_EQUAL(p.per_permutation.size(), 6u);
  for (const auto& b : p.per_permutation) {
    BOOST_REQUIRE(b.best);
    BOOST_TEST(b.best->permutation == b.permutation);
    for (const auto& s : solved.solutions) {
      if (s.permutation == b.permutation) BOOST_TEST(b.best->analytic_remainder <= s.analytic_remainder);
      BOOST_TEST(p.best->analytic_remainder <= s.analytic_remainder);
    }
  }
  double least = 1e300;
  for (std::size_t k = 0; k < 6; ++k) least = std::min(least, p.reference_remainders[k]);
  BOOST_TEST(p.reference_remainder == least);
  BOOST_REQUIRE(p.ratio);
  BOOST_TEST(*p.ratio == least / p.best->analytic_remainder * std::pow(12.0 / 9.0, 4), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(p.singular.empty());
}

BOOST_AUTO_TEST_CASE(a_flat_body_is_kept_and_its_singular_systems_recorded) {
  // t = 0: I1 + I2 = I3. Every system is solved or recorded as singular, none is lost.
  const auto g = solver::grid_point(4, 2, 0);
  BOOST_TEST(g.flat);
  const auto solved = solver::solve_dedicated(g.body, solver::family_schemes("N"), bch::permutation_names(), 40);
  const auto p = solver::summarize_family(g.body, "N", solved);
  std::size_t degenerate = 0;
  for (const auto& r : solved.systems) degenerate += r.degenerate ? 1 : 0;
  BOOST_TEST(p.singular.size() == degenerate);
  BOOST_TEST(solved.systems.size() == 42u);
}

BOOST_AUTO_TEST_SUITE_END()  // body_map_test
