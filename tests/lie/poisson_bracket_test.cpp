// The Lie–Poisson bracket: the explicit brackets (16)–(20), the Lie-algebra axioms and the
// Leibniz rule on random polynomials (replayable seed), the Casimir, and agreement between
// the coefficient rings.
#include <boost/test/unit_test.hpp>

#include <random>

#include "random_seed.hpp"
#include "rotlie/lie/coefficient_ring_ginac.hpp"
#include "rotlie/lie/poisson_bracket.hpp"

BOOST_AUTO_TEST_SUITE(poisson_bracket_test)

using namespace rotlie::lie;
using rpoly = polynomial<cln::cl_RA>;

namespace {

rpoly G(int i, std::uint32_t e = 1) { return rpoly::power_of(i, e); }

rpoly random_polynomial(std::mt19937_64& rng, std::uint32_t max_degree, int terms) {
  std::uniform_int_distribution<std::uint32_t> exponent(0, max_degree);
  std::uniform_int_distribution<long> numerator(-9, 9), denominator(1, 5);
  rpoly p;
  for (int t = 0; t < terms; ++t) {
    std::uint32_t e1 = exponent(rng), e2 = exponent(rng), e3 = exponent(rng);
    p.add_term(monomial(e1, e2, e3), cln::cl_RA(numerator(rng)) / cln::cl_RA(denominator(rng)));
  }
  return p;
}

void require_equal(const rpoly& got, const rpoly& want) {
  const rpoly diff = got - want;
  if (!diff.is_zero()) {
    std::ostringstream s;
    for (const auto& [m, c] : diff.terms()) s << " " << c << "*" << to_string(m);
    BOOST_FAIL("polynomials differ by" << s.str());
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(coordinate_brackets_follow_eq_16) {
  require_equal(poisson_bracket(G(1), G(2)), G(3));
  require_equal(poisson_bracket(G(2), G(3)), G(1));
  require_equal(poisson_bracket(G(3), G(1)), G(2));
  require_equal(poisson_bracket(G(2), G(1)), cln::cl_RA(-1) * G(3));
  BOOST_TEST(poisson_bracket(G(1), G(1)).is_zero());
}

BOOST_AUTO_TEST_CASE(order_two_brackets_eq_17) {
  const rpoly W = G(1) * G(2) * G(3);
  require_equal(poisson_bracket(G(1, 2), G(2, 2)), cln::cl_RA(4) * W);
  require_equal(poisson_bracket(G(2, 2), G(3, 2)), cln::cl_RA(4) * W);
  require_equal(poisson_bracket(G(3, 2), G(1, 2)), cln::cl_RA(4) * W);
}

BOOST_AUTO_TEST_CASE(order_three_brackets_eqs_18_to_20) {
  const rpoly W = G(1) * G(2) * G(3);
  auto sq = [](int i, int j) { return G(i, 2) * G(j, 2); };
  require_equal(poisson_bracket(G(1, 2), W), cln::cl_RA(2) * (sq(1, 3) - sq(1, 2)));  // (18)
  require_equal(poisson_bracket(G(2, 2), W), cln::cl_RA(2) * (sq(2, 1) - sq(2, 3)));  // (19)
  require_equal(poisson_bracket(G(3, 2), W), cln::cl_RA(2) * (sq(3, 2) - sq(3, 1)));  // (20)
}

BOOST_AUTO_TEST_CASE(antisymmetry_jacobi_and_leibniz_on_random_polynomials) {
  std::mt19937_64 rng(rotlie::test::test_seed("antisymmetry_jacobi_and_leibniz"));
  for (int trial = 0; trial < 40; ++trial) {
    const rpoly f = random_polynomial(rng, 4, 4), g = random_polynomial(rng, 4, 4), h = random_polynomial(rng, 3, 3);
    require_equal(poisson_bracket(f, g), cln::cl_RA(-1) * poisson_bracket(g, f));
    const rpoly jacobi = poisson_bracket(f, poisson_bracket(g, h)) + poisson_bracket(g, poisson_bracket(h, f)) +
                         poisson_bracket(h, poisson_bracket(f, g));
    BOOST_TEST(jacobi.is_zero());
    require_equal(poisson_bracket(f, g * h), poisson_bracket(f, g) * h + g * poisson_bracket(f, h));
  }
}

BOOST_AUTO_TEST_CASE(casimir_commutes_with_everything) {
  std::mt19937_64 rng(rotlie::test::test_seed("casimir_commutes_with_everything"));
  const rpoly G2 = casimir<cln::cl_RA>();
  for (int trial = 0; trial < 40; ++trial) BOOST_TEST(poisson_bracket(G2, random_polynomial(rng, 6, 6)).is_zero());
  // ... and G²/(2I2) commutes with R1 and R3 of the RS splitting (section 3.1.2): any G_i² will do.
  BOOST_TEST(poisson_bracket(G2, G(1, 2)).is_zero());
  BOOST_TEST(poisson_bracket(G2, G(3, 2)).is_zero());
}

BOOST_AUTO_TEST_CASE(symbolic_coefficients_agree_with_rationals) {
  // The same bracket with GiNaC coefficients, then the symbols substituted, equals the
  // rational computation with the substituted values.
  const GiNaC::symbol I1("I1"), I2("I2");
  using spoly = polynomial<GiNaC::ex>;
  const spoly A = spoly::term(monomial(2, 0, 0), 1 / (2 * I1));
  const spoly B = spoly::term(monomial(0, 2, 0), 1 / (2 * I2));
  const spoly AB = poisson_bracket(A, poisson_bracket(A, B));
  const rpoly a = rpoly::term(monomial(2, 0, 0), cln::cl_RA(1) / 6);   // I1 = 3
  const rpoly b = rpoly::term(monomial(0, 2, 0), cln::cl_RA(1) / 10);  // I2 = 5
  const rpoly ab = poisson_bracket(a, poisson_bracket(a, b));
  BOOST_TEST(AB.size() == ab.size());
  for (const auto& [m, c] : AB.terms()) {
    const GiNaC::ex value = c.subs(GiNaC::lst{I1 == 3, I2 == 5});
    const GiNaC::numeric want(cln::cl_N(ab.coefficient(m)));
    BOOST_TEST((value - want).is_zero(), "coefficient of " << to_string(m));
  }
}

BOOST_AUTO_TEST_CASE(double_coefficients_agree_with_rationals) {
  using dpoly = polynomial<double>;
  const dpoly f = dpoly::term(monomial(3, 1, 0), 0.5) + dpoly::term(monomial(0, 2, 2), -2.0);
  const dpoly g = dpoly::term(monomial(1, 1, 1), 3.0);
  const rpoly fr = rpoly::term(monomial(3, 1, 0), cln::cl_RA(1) / 2) + rpoly::term(monomial(0, 2, 2), -2);
  const rpoly gr = rpoly::term(monomial(1, 1, 1), 3);
  const dpoly h = poisson_bracket(f, g);
  const rpoly hr = poisson_bracket(fr, gr);
  BOOST_TEST(h.size() == hr.size());
  for (const auto& [m, c] : hr.terms()) BOOST_TEST(h.coefficient(m) == cln::double_approx(c));
}

BOOST_AUTO_TEST_SUITE_END()  // poisson_bracket_test
