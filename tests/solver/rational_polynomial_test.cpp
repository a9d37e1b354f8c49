// Exact univariate algebra: Sturm isolation counts every real root once, refinement reaches the
// requested width, multiple roots are counted once, roots exactly at bisection points are found.
#include <boost/test/unit_test.hpp>

#include <random>

#include "random_seed.hpp"
#include <cln/rational_io.h>

#include "rotlie/solver/rational_polynomial.hpp"

BOOST_AUTO_TEST_SUITE(rational_polynomial_test)

using namespace rotlie::solver;
using cln::cl_RA;

namespace {
rational_polynomial from_roots(const std::vector<cl_RA>& roots) {
  std::vector<cl_RA> c{1};
  for (const auto& r : roots) {  // multiply by (x − r)
    std::vector<cl_RA> n(c.size() + 1, 0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      n[i + 1] = n[i + 1] + c[i];
      n[i] = n[i] - r * c[i];
    }
    c = n;
  }
  return rational_polynomial(c);
}
}  // namespace

BOOST_AUTO_TEST_CASE(rational_roots_found_exactly_once) {
  std::mt19937_64 rng(rotlie::test::test_seed("rational_roots_found_exactly_once"));
  std::uniform_int_distribution<int> num(-30, 30), den(1, 7);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<cl_RA> roots;
    for (int i = 0; i < 1 + trial % 6; ++i) roots.push_back(cl_RA(num(rng)) / den(rng));
    roots.push_back(roots.front());  // a double root
    const auto p = from_roots(roots);
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    const auto found = isolate_real_roots(p);
    BOOST_REQUIRE(found.size() == roots.size());
    const auto sf = p.square_free();
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const cl_RA x = refine_root(sf, found[i], cl_RA(1) / 1000000000);
      BOOST_TEST(cln::double_approx(cln::abs(x - roots[i])) < 1e-9);
    }
  }
}

BOOST_AUTO_TEST_CASE(irrational_roots_to_fifty_digits) {
  // x² − 2: ±√2; x³ − 2x − 5 (Wallis): one real root 2.0945514815423265914823865405793029638573…
  const auto p = rational_polynomial({-2, 0, 1});
  const auto r = isolate_real_roots(p);
  BOOST_REQUIRE(r.size() == 2u);
  const cl_RA w = cln::recip(cln::expt(cl_RA(10), 50));
  const cl_RA s = refine_root(p, r[1], w);
  BOOST_TEST(cln::double_approx(cln::abs(s * s - 2)) < 1e-49);
  const auto wallis = rational_polynomial({-5, -2, 0, 1});
  const auto rw = isolate_real_roots(wallis);
  BOOST_REQUIRE(rw.size() == 1u);
  const cl_RA x = refine_root(wallis, rw[0], w);
  BOOST_TEST(cln::double_approx(cln::abs(x - cl_RA(20945514815423265LL) / cl_RA(10000000000000000LL))) < 1e-15);
  BOOST_TEST(cln::double_approx(cln::abs(wallis(x))) < 1e-48);
}

// The Newton polisher against exact bisection (a second method): the same root to the width asked,
// on random integer polynomials of degree up to 40 whose real roots are isolated first.
BOOST_AUTO_TEST_CASE(polisher_agrees_with_exact_bisection) {
  std::mt19937_64 rng(rotlie::test::test_seed("polisher_agrees_with_exact_bisection"));
  std::uniform_int_distribution<long> coefficient(-1000000, 1000000);
  const int digits = 40;
  const cl_RA width = cln::recip(cln::expt(cl_RA(10), digits + 10));
  int roots_checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<cl_RA> c;
    for (int i = 0; i <= 5 + 2 * trial - trial / 2; ++i) c.push_back(coefficient(rng));
    const auto p = rational_polynomial(c).square_free();
    const root_polisher polisher(p, digits);
    for (const auto& r : isolate_real_roots_of_square_free(p)) {
      const cl_RA fast = polisher.polish(r), slow = refine_root(p, r, width);
      BOOST_TEST(cln::abs(fast - slow) <= width);
      ++roots_checked;
    }
    BOOST_TEST(polisher.uncertified() == 0);
  }
  BOOST_TEST(roots_checked > 20);
}

// The modular gcd against Euclid over Q (a second method), on products with a known common factor
// with large coefficients and on coprime pairs.
BOOST_AUTO_TEST_CASE(modular_gcd_agrees_with_euclid) {
  std::mt19937_64 rng(rotlie::test::test_seed("modular_gcd_agrees_with_euclid"));
  std::uniform_int_distribution<long> coefficient(-1000000000, 1000000000);
  const auto random_polynomial = [&](int degree) {
    std::vector<cl_RA> c;
    for (int i = 0; i <= degree; ++i) c.push_back(cl_RA(coefficient(rng)) / (1 + (coefficient(rng) & 1023)));
    if (cln::zerop(c.back())) c.back() = 1;
    return rational_polynomial(c);
  };
  const auto times = [](const rational_polynomial& a, const rational_polynomial& b) {
    std::vector<cl_RA> c(a.coefficients().size() + b.coefficients().size() - 1, 0);
    for (std::size_t i = 0; i < a.coefficients().size(); ++i)
      for (std::size_t j = 0; j < b.coefficients().size(); ++j) c[i + j] = c[i + j] + a.coefficients()[i] * b.coefficients()[j];
    return rational_polynomial(c);
  };
  for (int trial = 0; trial < 12; ++trial) {
    const auto common = random_polynomial(1 + trial % 5), f = random_polynomial(3 + trial), g = random_polynomial(2 + trial / 2);
    const auto a = times(times(common, common), f), b = times(common, g);
    const auto fast = modular_gcd(a, b), slow = gcd(a, b);
    BOOST_TEST(fast.degree() == slow.degree());
    BOOST_TEST((fast.coefficients() == slow.coefficients()));
    BOOST_TEST(modular_gcd(f, g).degree() == gcd(f, g).degree());
  }
}

BOOST_AUTO_TEST_CASE(no_real_roots_and_refusals) {
  BOOST_TEST(isolate_real_roots(rational_polynomial({1, 0, 1})).empty());  // x² + 1
  BOOST_TEST(isolate_real_roots(rational_polynomial({5})).empty());
  BOOST_CHECK_THROW(isolate_real_roots(rational_polynomial{}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // rational_polynomial_test
