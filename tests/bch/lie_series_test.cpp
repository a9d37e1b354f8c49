// BCH series: Lyndon words, coefficients against an independent table (HaraldHofstaetter/BCH,
// Lyndon basis, A < B), odd degrees only for the symmetric series, and the series evaluated on
// random matrices against log(expm(X) expm(Y)) by power series.
#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>
#include <random>

#include "random_seed.hpp"
#include "rotlie/bch/evaluate.hpp"
#include "rotlie/bch/lie_series.hpp"
#include "rotlie/lie/free_lie_dimension.hpp"

BOOST_AUTO_TEST_SUITE(lie_series_test)

using namespace rotlie::bch;

namespace {

word w(const std::string& s) {
  word out;
  for (char c : s) out.push_back(static_cast<std::uint8_t>(c - 'A'));
  return out;
}

cln::cl_RA q(long n, long d) { return cln::cl_RA(n) / cln::cl_RA(d); }

struct matrix_algebra {
  Eigen::MatrixXd bracket(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) const { return a * b - b * a; }
  void add_scaled(Eigen::MatrixXd& acc, const cln::cl_RA& c, const Eigen::MatrixXd& x) const {
    acc += cln::double_approx(c) * x;
  }
  Eigen::MatrixXd zero() const { return Eigen::MatrixXd::Zero(n, n); }
  long n;
};

// The reference by power series, not by the Lie series under test (and without Eigen's
// MatrixFunctions, the slowest header of the test suites to compile): for ‖X‖ ≤ 0.15 the exponential's
// 30 terms and, for ‖M − 1‖ ≤ 0.6, the logarithm's 80 terms (0.6⁸⁰ ≈ 2e-18) are exact to far below 1e-16.
Eigen::MatrixXd exp_series(const Eigen::MatrixXd& x) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Identity(x.rows(), x.cols()), term = sum;
  for (int k = 1; k < 30; ++k) {
    term = term * x / k;
    sum += term;
  }
  return sum;
}

Eigen::MatrixXd log_series(const Eigen::MatrixXd& m) {
  const Eigen::MatrixXd y = m - Eigen::MatrixXd::Identity(m.rows(), m.cols());
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(m.rows(), m.cols()), power = Eigen::MatrixXd::Identity(m.rows(), m.cols());
  for (int k = 1; k < 80; ++k) {
    power = power * y;
    sum += (k % 2 ? 1.0 : -1.0) / k * power;
  }
  return sum;
}

}  // namespace

BOOST_AUTO_TEST_CASE(lyndon_words_are_counted_by_witts_formula) {
  for (int letters = 2; letters <= 3; ++letters) {
    const auto words = lyndon_words(letters, 9);
    for (int d = 1; d <= 9; ++d) {
      const auto n = std::count_if(words.begin(), words.end(), [&](const word& x) { return (int)x.size() == d; });
      BOOST_TEST(n == rotlie::lie::free_lie_dimension(letters, d), letters << " letters, degree " << d);
    }
    for (const auto& x : words) BOOST_TEST(is_lyndon(x));
  }
  BOOST_TEST(bracket_text(w("AABAB")) == "[[A,[A,B]],[A,B]]");
  BOOST_TEST(bracket_text(w("ABB")) == "[[A,B],B]");
}

BOOST_AUTO_TEST_CASE(bch_coefficients_match_an_independent_table) {
  const auto s = bch_series(8);
  // HaraldHofstaetter/BCH README, Lyndon basis: every nonzero coefficient up to degree 6.
  const std::vector<std::pair<std::string, cln::cl_RA>> want = {
      {"A", 1},           {"B", 1},           {"AB", q(1, 2)},      {"AAB", q(1, 12)},    {"ABB", q(1, 12)},
      {"AABB", q(1, 24)}, {"AAAAB", q(-1, 720)}, {"AAABB", q(1, 180)}, {"AABAB", q(1, 360)}, {"AABBB", q(1, 180)},
      {"ABABB", q(1, 120)}, {"ABBBB", q(-1, 720)}, {"AAAABB", q(-1, 1440)}, {"AAABAB", q(1, 720)},
      {"AAABBB", q(1, 360)}, {"AABABB", q(1, 240)}, {"AABBBB", q(-1, 1440)}};
  std::size_t up_to_6 = 0;
  for (const auto& [x, c] : s.coefficients) up_to_6 += x.size() <= 6;
  BOOST_TEST(up_to_6 == want.size());
  for (const auto& [x, c] : want) {
    const auto it = s.coefficients.find(w(x));
    BOOST_TEST((it != s.coefficients.end() && it->second == c), x);
  }
  // nonzero Lyndon coefficients per degree, from the same table (degrees 1–8)
  const std::size_t counts[] = {2, 1, 2, 1, 6, 5, 18, 17};
  for (int d = 1; d <= 8; ++d) BOOST_TEST(s.nonzero_at_degree(d) == counts[d - 1], "degree " << d);
  // two degree-8 values quoted in the table: 1/60480 [A,[A,[A,[A,[A,[[A,B],B]]]]]] and 23/120960 [A,[A,[A,[[[[A,B],B],B],B]]]]
  BOOST_TEST((s.coefficients.at(w("AAAAAABB")) == q(1, 60480)));
  BOOST_TEST((s.coefficients.at(w("AAAABBBB")) == q(23, 120960)));
}

BOOST_AUTO_TEST_CASE(symmetric_bch_has_only_odd_degrees) {
  const auto s = symmetric_bch_series(9);
  for (int d = 2; d <= 9; d += 2) BOOST_TEST(s.nonzero_at_degree(d) == 0u, "degree " << d);
  for (int d = 1; d <= 9; d += 2) BOOST_TEST(s.nonzero_at_degree(d) > 0u, "degree " << d);
  // log(e^X e^Y e^X) = 2X + Y − (1/6)[X,[X,Y]] + (1/6)[[X,Y],Y] + …  (Lyndon basis; Strang with A = 2X)
  BOOST_TEST((s.coefficients.at(w("A")) == 2));
  BOOST_TEST((s.coefficients.at(w("B")) == 1));
  BOOST_TEST((s.coefficients.at(w("AAB")) == q(-1, 6)));
  BOOST_TEST((s.coefficients.at(w("ABB")) == q(1, 6)));
}

BOOST_AUTO_TEST_CASE(series_match_matrix_logarithms_with_error_falling_with_degree) {
  std::mt19937_64 rng(rotlie::test::test_seed("series_match_matrix_logarithms"));
  std::normal_distribution<double> normal;
  const long n = 4;
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::MatrixXd X(n, n), Y(n, n);
    for (long i = 0; i < n * n; ++i) X.data()[i] = normal(rng), Y.data()[i] = normal(rng);
    // Random directions at a fixed size: the truncation error after degree d scales like
    // (‖X‖ + ‖Y‖)^(d+1), so the final bound below holds for every draw, not only typical ones.
    X *= 0.15 / X.norm();
    Y *= 0.15 / Y.norm();
    const Eigen::MatrixXd eX = exp_series(X), eY = exp_series(Y);
    BOOST_TEST_REQUIRE((eX * eY * eX - Eigen::MatrixXd::Identity(n, n)).norm() < 0.6);  // the log series' range
    const Eigen::MatrixXd exact = log_series(eX * eY);
    const Eigen::MatrixXd exact_sym = log_series(eX * eY * eX);
    double previous = 1, previous_sym = 1;
    for (int degree = 2; degree <= 10; degree += 2) {
      const matrix_algebra algebra{n};
      const double err = (evaluate(bch_series(degree), std::vector<Eigen::MatrixXd>{X, Y}, algebra) - exact).norm();
      const double err_sym =
          (evaluate(symmetric_bch_series(degree + 1), std::vector<Eigen::MatrixXd>{X, Y}, algebra) - exact_sym).norm();
      BOOST_TEST_MESSAGE("degree " << degree << ": error " << err << ", symmetric (degree " << degree + 1 << ") " << err_sym);
      BOOST_TEST((err < previous * 0.1 || err < 1e-14), "degree " << degree << " error " << err);
      BOOST_TEST((err_sym < previous_sym * 0.1 || err_sym < 1e-14), "degree " << degree + 1 << " error " << err_sym);
      previous = err;
      previous_sym = err_sym;
    }
    BOOST_TEST(previous < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(degree_outside_the_supported_range_is_refused) {
  BOOST_CHECK_THROW(bch_series(0), std::invalid_argument);
  BOOST_CHECK_THROW(symmetric_bch_series(max_bch_degree + 1), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // lie_series_test
