// Two equations in two unknowns: back-substitution (the fast path) against pairing (both resultants,
// every pair tested: the second method) on every N system for water and for a near-flat body, and
// on constructed systems with a root at infinity, a shared factor, and two solutions over one u.
#include <boost/test/unit_test.hpp>

#include <cln/rational_io.h>

#include <cmath>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/solver/critical_points.hpp"
#include "rotlie/solver/real_solutions.hpp"
#include "rotlie/solver/residue_field.hpp"

BOOST_AUTO_TEST_SUITE(real_solutions_test)

using namespace rotlie;
using lie::coefficient_polynomial;

namespace {

const coefficient_polynomial x = coefficient_polynomial::unknown(0), y = coefficient_polynomial::unknown(1);

void same_points(const solver::system_result& a, const solver::system_result& b, const cln::cl_RA& width) {
  BOOST_REQUIRE(a.points.size() == b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    BOOST_TEST(cln::abs(a.points[i].u - b.points[i].u) <= width);
    BOOST_TEST(cln::abs(a.points[i].v - b.points[i].v) <= width);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(back_substitution_equals_pairing_on_every_n_system) {
  const int digits = 40;
  const cln::cl_RA width = cln::recip(cln::expt(cln::cl_RA(10), digits + 8));
  int systems = 0, back_substituted = 0;
  for (const std::string body_name : {"water", "1/3,0.7,1"}) {
    const auto body = lie::parse_moments(body_name);
    const std::array<cln::cl_RA, 3> w{cln::recip(body.I[0]), cln::recip(body.I[1]), cln::recip(body.I[2])};
    for (int n = 1; n <= 7; ++n)
      for (const auto& perm : bch::permutation_names()) {
        const auto s = *bch::find_named_scheme("N" + std::to_string(n));
        const auto k = bch::compute_exact_modified_hamiltonian(bch::layout_scheme(s.word, s.split, perm), w, 3);
        const auto p1 = k.remainder[3].coefficient(lie::monomial(2, 2, 0)), p2 = k.remainder[3].coefficient(lie::monomial(2, 0, 2));
        const auto fast = solver::solve_two_equations(p1, p2, 0, 1, digits);
        const auto paired = solver::solve_two_equations(p1, p2, 0, 1, digits, solver::solve_method::pairing);
        BOOST_TEST_CONTEXT(body_name << " N" << n << " " << perm) { same_points(fast, paired, width); }
        ++systems;
        back_substituted += fast.paired ? 0 : 1;
      }
  }
  BOOST_TEST(systems == 84);
  BOOST_TEST(back_substituted == systems);  // no system needs the full fallback
}

// The Lagrange systems of section 3.4 (R and P for water) whose eliminants have multiple roots:
// rational (points at infinity), irrational (P4 ACB: two critical points above u = 0.2337) and the
// spurious A = B = 0 roots; the fast path against pairing, point by point.
BOOST_AUTO_TEST_CASE(critical_points_equal_pairing_where_the_eliminant_has_multiple_roots) {
  const auto body = lie::parse_moments("water");
  const std::array<cln::cl_RA, 3> w{cln::recip(body.I[0]), cln::recip(body.I[1]), cln::recip(body.I[2])};
  const int digits = 40;
  for (const auto& [scheme, perm] : std::vector<std::pair<std::string, std::string>>{{"P4", "ACB"}, {"P9", "ABC"}, {"R", "CAB"}}) {
    const auto s = *bch::find_named_scheme(scheme);
    const auto k = bch::compute_exact_modified_hamiltonian(bch::layout_scheme(s.word, s.split, perm), w, 5);
    const auto g1 = k.remainder[3].coefficient(lie::monomial(2, 2, 0)), g2 = k.remainder[3].coefficient(lie::monomial(2, 0, 2));
    coefficient_polynomial f;
    for (const auto& [m, q] : k.remainder[5].terms()) f += q * q;
    const auto fast = solver::constrained_critical_points(f, g1, g2, digits);
    const auto paired = solver::constrained_critical_points(f, g1, g2, digits, solver::solve_method::pairing);
    BOOST_TEST_CONTEXT(scheme << " " << perm) {
      BOOST_REQUIRE(fast.points.size() == paired.points.size());
      for (std::size_t i = 0; i < fast.points.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
          BOOST_TEST(cln::double_approx(cln::abs(fast.points[i].values[c] - paired.points[i].values[c])) < 1e-45);
    }
  }
}

BOOST_AUTO_TEST_CASE(root_at_infinity_is_not_a_solution) {
  // x y − 1 = 0 and x y + x − 2 = 0: Res_y ∝ x(x − 1); x = 0 is a common zero of both leading
  // coefficients (a point at infinity), x = 1 gives the one solution (1, 1).
  const auto e1 = x * y - 1, e2 = x * y + x - 2;
  const auto r = solver::solve_two_equations(e1, e2, 0, 1, 20);
  BOOST_TEST(!r.paired);
  BOOST_REQUIRE(r.points.size() == 1u);
  BOOST_TEST(r.points[0].u == 1);
  BOOST_TEST(cln::double_approx(cln::abs(r.points[0].v - 1)) < 1e-25);
}

BOOST_AUTO_TEST_CASE(two_solutions_over_one_u_are_both_found) {
  // y² = x and x = 4: (4, ±2) share u = 4, a double root of the eliminant in x, rational: solved
  // exactly through gcd(e1(4, ·), e2(4, ·)).
  const auto r = solver::solve_two_equations(y * y - x, x - 4, 0, 1, 20);
  BOOST_TEST(!r.paired);
  BOOST_TEST(r.multiple_roots == 0);
  BOOST_REQUIRE(r.points.size() == 2u);
  BOOST_TEST(cln::double_approx(r.points[0].v) == -2.0, boost::test_tools::tolerance(1e-20));
  BOOST_TEST(cln::double_approx(r.points[1].v) == 2.0, boost::test_tools::tolerance(1e-20));
  // y² = x and x² = 2: the eliminant (x² − 2)² has irrational double roots ±√2, solved by a gcd in
  // Q(√2): (√2, ±2^(1/4)); nothing real above −√2. Pairing (the second method) agrees.
  const auto q = solver::solve_two_equations(y * y - x, x * x - 2, 0, 1, 30);
  BOOST_TEST(q.multiple_roots == 0);
  same_points(q, solver::solve_two_equations(y * y - x, x * x - 2, 0, 1, 30, solver::solve_method::pairing),
              cln::recip(cln::expt(cln::cl_RA(10), 35)));
  BOOST_REQUIRE(q.points.size() == 2u);
  BOOST_TEST(cln::double_approx(q.points[0].u) == std::sqrt(2.0), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(cln::double_approx(q.points[1].v) == std::pow(2.0, 0.25), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(cln::double_approx(q.points[0].v) == -std::pow(2.0, 0.25), boost::test_tools::tolerance(1e-15));
}

// Q(α) arithmetic where the modulus is reducible: (u² − 2)(u² − 3) with α = √3; the element u² − 3
// is zero there, so the modulus shrinks to u² − 3, and u² − 2 is inverted modulo it (inverse 1).
BOOST_AUTO_TEST_CASE(residue_field_splits_a_reducible_modulus) {
  using solver::rational_polynomial;
  solver::residue_field field(rational_polynomial({6, 0, -5, 0, 1}), cln::cl_RA(17) / 10, cln::cl_RA(18) / 10);
  BOOST_TEST(field.is_zero(rational_polynomial({-3, 0, 1})));
  BOOST_TEST(field.modulus().degree() == 2);
  BOOST_TEST(!field.is_zero(rational_polynomial({-2, 0, 1})));
  const auto inverse = field.inverse(rational_polynomial({-2, 0, 1}));
  BOOST_TEST(inverse.degree() == 0);
  BOOST_TEST(inverse.coefficients()[0] == 1);
}

BOOST_AUTO_TEST_CASE(shared_factors_are_degenerate) {
  BOOST_TEST(solver::solve_two_equations((x - y) * (x + 1), (x - y) * (y - 2), 0, 1, 20).degenerate);
  BOOST_TEST(solver::solve_two_equations((x - 3) * (y + 1), (x - 3) * (y - 2), 0, 1, 20).degenerate);  // free of y
  BOOST_TEST(!solver::solve_two_equations(x * x + y * y - 2, x - y, 0, 1, 20).degenerate);
}

BOOST_AUTO_TEST_SUITE_END()  // real_solutions_test
