// The free-algebra BCH engine against independent values: the logarithm in the free associative
// algebra projected by the residual method (a second algorithm), the published counts of nonzero
// coefficients per degree, the vanishing even degrees of the symmetric series, the direct
// projection of XY against its derivation from SYM, and a float128 matrix-logarithm check at
// degree 20; the three-letter series against nested two-letter ones.
#include <boost/test/unit_test.hpp>

#include <array>
#include <random>

#include "rotlie/bch/evaluate.hpp"
#include "rotlie/bch/free_bch.hpp"
#include "rotlie/bch/word_series.hpp"
#include "rotlie/lie/free_lie_dimension.hpp"

BOOST_AUTO_TEST_SUITE(free_bch_test)

using namespace rotlie::bch;

namespace {

__extension__ using quad = __float128;
constexpr int dim = 3;
using matrix = std::array<std::array<quad, dim>, dim>;

matrix operator*(const matrix& a, const matrix& b) {
  matrix c{};
  for (int i = 0; i < dim; ++i)
    for (int k = 0; k < dim; ++k)
      for (int j = 0; j < dim; ++j) c[i][j] += a[i][k] * b[k][j];
  return c;
}
matrix operator+(matrix a, const matrix& b) {
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) a[i][j] += b[i][j];
  return a;
}
matrix scaled(matrix a, quad s) {
  for (auto& row : a)
    for (auto& x : row) x *= s;
  return a;
}
matrix identity() {
  matrix a{};
  for (int i = 0; i < dim; ++i) a[i][i] = 1;
  return a;
}
double distance(const matrix& a, const matrix& b) {
  double d = 0;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) d = std::max(d, std::abs(static_cast<double>(a[i][j] - b[i][j])));
  return d;
}
matrix expm(const matrix& x) {  // Taylor series, ‖x‖ small: 60 terms reach float128 precision
  matrix sum = identity(), term = identity();
  for (int k = 1; k < 60; ++k) {
    term = scaled(term * x, quad(1) / k);
    sum = sum + term;
  }
  return sum;
}
matrix logm(const matrix& m) {  // log(I + y) = Σ (−1)^{k+1} y^k / k, ‖y‖ ≤ 0.3: 150 terms
  const matrix y = m + scaled(identity(), -1);
  matrix sum{}, power = identity();
  for (int k = 1; k < 150; ++k) {
    power = power * y;
    sum = sum + scaled(power, quad(k % 2 ? 1 : -1) / k);
  }
  return sum;
}

struct quad_matrix_algebra {
  matrix bracket(const matrix& a, const matrix& b) const { return a * b + scaled(b * a, -1); }
  void add_scaled(matrix& acc, const cln::cl_RA& c, const matrix& x) const {
    // c to float128 through numerator / denominator (both exact below 2^113 here)
    const quad v = static_cast<quad>(cln::double_approx(cln::numerator(c))) / static_cast<quad>(cln::double_approx(cln::denominator(c)));
    acc = acc + scaled(x, v);
  }
  matrix zero() const { return {}; }
};

matrix random_matrix(std::mt19937_64& rng, double size) {
  std::uniform_real_distribution<double> u(-1, 1);
  matrix a{};
  for (auto& row : a)
    for (auto& x : row) x = static_cast<quad>(size * u(rng));
  return a;
}

lie_series truncated(const lie_series& s, int degree) {
  lie_series t = s;
  std::erase_if(t.coefficients, [&](const auto& kv) { return static_cast<int>(kv.first.size()) > degree; });
  return t;
}

}  // namespace

BOOST_AUTO_TEST_CASE(basis_has_witt_many_words_and_standard_factorisations) {
  for (int letters = 2; letters <= 3; ++letters) {
    const lyndon_basis b(letters, 10);
    for (int d = 1; d <= 10; ++d)
      BOOST_TEST(static_cast<long>(b.end(d) - b.begin(d)) == static_cast<long>(rotlie::lie::free_lie_dimension(letters, d)));
    for (std::size_t i = 0; i < b.size(); ++i) {
      BOOST_TEST(is_lyndon(b.word_at(i)));
      if (b.length(i) < 2) continue;
      const auto [u, v] = standard_factorization(b.word_at(i));
      BOOST_TEST((b.word_at(b.left(i)) == u && b.word_at(b.right(i)) == v));
    }
  }
}

// A second algorithm: the logarithm expanded in the free associative algebra, then the residual
// projection (word_series / lyndon_coordinates), exact.
BOOST_AUTO_TEST_CASE(all_series_equal_the_free_associative_logarithm) {
  const int n = 9;
  const auto a = word_series::exp_of_letter(0, n), b = word_series::exp_of_letter(1, n), c = word_series::exp_of_letter(2, n);
  word_series half_a(n);
  for (const auto& [w, x] : a.degree(1)) half_a.add(w, x / 2);
  // e^{A/2} by the exponential of the half letter
  word_series e_half = word_series::one(n), power = word_series::one(n);
  cln::cl_RA factorial = 1;
  for (int k = 1; k <= n; ++k) {
    power = power * half_a;
    factorial = factorial * k;
    word_series term = power;
    term *= cln::recip(factorial);
    e_half += term;
  }
  const std::vector<std::pair<free_series, lie_series>> expected = {
      {free_series::xy, lyndon_coordinates(log(a * b), 2)},
      {free_series::xyx, lyndon_coordinates(log(a * b * a), 2)},
      {free_series::sym, lyndon_coordinates(log(e_half * b * e_half), 2)},
      {free_series::xyz, lyndon_coordinates(log(a * b * c), 3)}};
  for (const auto& [name, want] : expected) {
    const auto got = compute_free_series(name, n);
    std::size_t nonzero = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const auto it = want.coefficients.find(got.basis->word_at(i));
      const cln::cl_RA w = it == want.coefficients.end() ? cln::cl_RA(0) : it->second;
      BOOST_TEST((got.coefficient(i) == w), series_name(name) << " " << got.basis->foliage(i));
      nonzero += got.numerator[i] != 0;
    }
    BOOST_TEST(nonzero == want.coefficients.size());
  }
}

// Casas & Murua (2009), J. Math. Phys. 50, 033513, Table 1: nonzero BCH coefficients in the
// Lyndon basis per degree (the same counts come out of the C program HaraldHofstaetter/BCH).
BOOST_AUTO_TEST_CASE(nonzero_counts_per_degree_are_the_published_ones) {
  const std::vector<std::size_t> published = {2, 1, 2, 1, 6, 5, 18, 17, 55, 55, 186, 185, 630, 629, 2181, 2181, 7710, 7709, 27594, 27593};
  const auto s = compute_free_series(free_series::xy, 20);
  for (int d = 1; d <= 20; ++d) BOOST_TEST(s.nonzero_at_degree(d) == published[static_cast<std::size_t>(d - 1)], "degree " << d);
  // the common denominator of degree 20 is the least one: the reduction divided out every common factor
  BOOST_TEST(to_string(s.denominator[20]) == "102181884343418880000");
}

BOOST_AUTO_TEST_CASE(symmetric_series_vanish_at_even_degrees_when_solved) {
  series_options all;
  all.direct = true;  // solve the even degrees instead of assuming they vanish
  for (const auto name : {free_series::xyx, free_series::sym}) {
    const auto s = compute_free_series(name, 12, all);
    for (int d = 2; d <= 12; d += 2) BOOST_TEST(s.nonzero_at_degree(d) == 0u, series_name(name) << " degree " << d);
    for (int d = 1; d <= 11; d += 2) BOOST_TEST(s.nonzero_at_degree(d) > 0u);
    const auto fast = compute_free_series(name, 12);
    BOOST_TEST((fast.numerator == s.numerator && fast.denominator[11] == s.denominator[11]));
  }
}

BOOST_AUTO_TEST_CASE(xy_projected_directly_equals_xy_derived_from_sym) {
  series_options direct;
  direct.direct = true;
  direct.threads = 2;
  const auto a = compute_free_series(free_series::xy, 15, direct), b = compute_free_series(free_series::xy, 15);
  for (std::size_t i = 0; i < a.size(); ++i) BOOST_TEST((a.coefficient(i) == b.coefficient(i)), a.basis->foliage(i));
}

BOOST_AUTO_TEST_CASE(threads_do_not_change_the_result) {
  const auto one = compute_free_series(free_series::xyz, 9), two = compute_free_series(free_series::xyz, 9, {2, false});
  BOOST_TEST((one.numerator == two.numerator && one.denominator == two.denominator));
}

// log(e^X e^Y) of 3×3 matrices of size ε in float128 against the truncated series: the degree-20
// truncation is ε^21-close, and its degree-20 terms are needed to get there.
BOOST_AUTO_TEST_CASE(degree_20_series_matches_the_matrix_logarithm) {
  std::mt19937_64 rng(20);
  const double eps = 0.08;
  const matrix x = random_matrix(rng, eps), y = random_matrix(rng, eps);
  const matrix exact = logm(expm(x) * expm(y));
  const auto s = to_lie_series(compute_free_series(free_series::xy, 20));
  const quad_matrix_algebra algebra;
  const double e20 = distance(evaluate(s, std::vector<matrix>{x, y}, algebra), exact);
  const double e19 = distance(evaluate(truncated(s, 19), std::vector<matrix>{x, y}, algebra), exact);
  BOOST_TEST_MESSAGE("degree 19: " << e19 << ", degree 20: " << e20);
  BOOST_TEST(e20 < 1e-26);
  BOOST_TEST(e20 < e19 / 5);
  // the symmetric series at degree 19 against log(e^{X/2} e^Y e^{X/2})
  const matrix half = expm(scaled(x, quad(1) / 2));
  const matrix exact_sym = logm(half * expm(y) * half);
  const auto sym = to_lie_series(compute_free_series(free_series::sym, 19));
  BOOST_TEST(distance(evaluate(sym, std::vector<matrix>{x, y}, algebra), exact_sym) < 1e-26);
}

// log(e^X e^Y e^Z) = XY(XY(X, Y), Z): the three-letter series against the nested two-letter one on matrices.
BOOST_AUTO_TEST_CASE(three_letter_series_equals_nested_two_letter_series) {
  std::mt19937_64 rng(14);
  const double eps = 0.05;
  const matrix x = random_matrix(rng, eps), y = random_matrix(rng, eps), z = random_matrix(rng, eps);
  const quad_matrix_algebra algebra;
  const auto xy = to_lie_series(compute_free_series(free_series::xy, 14));
  const matrix nested = evaluate(xy, std::vector<matrix>{evaluate(xy, std::vector<matrix>{x, y}, algebra), z}, algebra);
  const auto xyz = to_lie_series(compute_free_series(free_series::xyz, 14));
  const matrix direct = evaluate(xyz, std::vector<matrix>{x, y, z}, algebra);
  const matrix exact = logm(expm(x) * expm(y) * expm(z));
  BOOST_TEST_MESSAGE("nested " << distance(nested, exact) << ", three letters " << distance(direct, exact));
  BOOST_TEST(distance(direct, nested) < 1e-18);
  BOOST_TEST(distance(direct, exact) < 1e-18);
}

BOOST_AUTO_TEST_CASE(degrees_outside_the_range_are_refused) {
  BOOST_CHECK_THROW(compute_free_series(free_series::xy, 0), std::invalid_argument);
  BOOST_CHECK_THROW(compute_free_series(free_series::sym, 21), std::invalid_argument);
  BOOST_CHECK_THROW(compute_free_series(free_series::xyz, 15), std::invalid_argument);
  BOOST_TEST(!parse_free_series("XZ").has_value());
}

BOOST_AUTO_TEST_SUITE_END()  // free_bch_test
