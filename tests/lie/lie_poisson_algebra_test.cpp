// The graded algebra L_k: dimensions, Theorems 1–2 up to order 40, the certificate against
// exact elimination (two methods), and the bases of section 2.1.1.
#include <boost/test/unit_test.hpp>

#include <random>

#include "random_seed.hpp"
#include "rotlie/lie/exact_echelon.hpp"
#include "rotlie/lie/lie_poisson_algebra.hpp"
#include "rotlie/lie/modular_rank.hpp"

BOOST_AUTO_TEST_SUITE(lie_poisson_algebra_test)

using namespace rotlie::lie;
using rpoly = polynomial<cln::cl_RA>;

namespace {

rpoly G(int i, std::uint32_t e = 1) { return rpoly::power_of(i, e); }
rpoly n(long v) { return rpoly::term(monomial(), v); }

}  // namespace

BOOST_AUTO_TEST_CASE(dimensions_of_the_first_five_orders) {
  const auto pieces = lie_poisson_algebra(5);
  const std::size_t want[] = {3, 1, 2, 3, 6};  // section 2.1.1
  for (std::size_t i = 0; i < 5; ++i) BOOST_TEST(pieces[i].dimension == want[i], "order " << i + 1);
}

BOOST_AUTO_TEST_CASE(theorems_1_and_2_hold_up_to_order_40) {
  const auto pieces = lie_poisson_algebra(40);
  BOOST_REQUIRE(pieces.size() == 40u);
  for (const auto& p : pieces) {
    BOOST_TEST(p.theorem1, "order " << p.order);
    BOOST_TEST(p.theorem2.has_value() == (p.order >= 3 && p.order % 2 == 1), "order " << p.order);
    if (p.theorem2) BOOST_TEST(*p.theorem2, "order " << p.order);
    BOOST_TEST(p.basis.size() == p.dimension);
  }
}

BOOST_AUTO_TEST_CASE(certificate_agrees_with_exact_elimination) {
  // Second method: rank by exact rational elimination of the brackets of the previous basis.
  const int K = 18;
  algebra_options exact;
  exact.exact_only = true;
  const auto certified = lie_poisson_algebra(K);
  const auto eliminated = lie_poisson_algebra(K, exact);
  for (int k = 0; k < K; ++k) {
    BOOST_TEST(certified[k].dimension == eliminated[k].dimension, "order " << k + 1);
    BOOST_TEST((eliminated[k].method == rank_method::exact_elimination));
    // and the two bases span the same space
    for (const auto& v : eliminated[k].basis) BOOST_TEST(in_span(certified[k].basis, v), "order " << k + 1);
  }
  for (int k = 1; k < K; ++k) BOOST_TEST((certified[k].method == rank_method::certificate), "order " << k + 1);
}

BOOST_AUTO_TEST_CASE(bases_of_orders_4_and_5_from_section_2_1_1) {
  const auto pieces = lie_poisson_algebra(5);
  const rpoly W = G(1) * G(2) * G(3);
  const std::vector<rpoly> order4 = {G(1, 2) * W, G(2, 2) * W, G(3, 2) * W};
  const std::vector<rpoly> order5 = {
      n(3) * W * W - G(1, 4) * G(2, 2), n(3) * W * W - G(2, 4) * G(3, 2), n(3) * W * W - G(3, 4) * G(1, 2),
      G(1, 4) * (G(2, 2) - G(3, 2)),    G(2, 4) * (G(3, 2) - G(1, 2)),    G(3, 4) * (G(1, 2) - G(2, 2))};
  for (const auto& [piece, family] : {std::pair{&pieces[3], &order4}, std::pair{&pieces[4], &order5}}) {
    exact_echelon echelon;
    for (const auto& v : *family) {
      BOOST_TEST(in_span(piece->basis, v), "element of L_" << piece->order);
      BOOST_TEST(echelon.add(v), "independent in L_" << piece->order);
    }
    BOOST_TEST(echelon.rank() == piece->dimension);
  }
  // Order 3: the three brackets (18)–(20) span L_3 and satisfy P1 + P2 + P3 = 0 (eq. 22), so dim 2.
  BOOST_TEST(!in_span(pieces[2].basis, G(1, 2) * G(2, 2)));
  BOOST_TEST(in_span(pieces[2].basis, G(1, 2) * G(2, 2) - G(2, 2) * G(3, 2)));
}

BOOST_AUTO_TEST_CASE(bound_attained_through_order_40) {
  for (const auto& p : lie_poisson_algebra(40)) BOOST_TEST(p.bound_attained(), "order " << p.order);
}

BOOST_AUTO_TEST_CASE(modular_rank_agrees_with_exact_rank_on_random_integer_vectors) {
  std::mt19937_64 rng(rotlie::test::test_seed("modular_rank_agrees_with_exact_rank"));
  std::uniform_int_distribution<int> coefficient(-3, 3), exponent(0, 3);
  for (int trial = 0; trial < 50; ++trial) {
    exact_echelon exact;
    modular_echelon modular;
    const int vectors = 2 + trial % 7;
    for (int v = 0; v < vectors; ++v) {
      rpoly p;
      for (int t = 0; t < 4; ++t)
        p.add_term(monomial(exponent(rng), exponent(rng), 0), coefficient(rng));
      exact.add(p);
      BOOST_REQUIRE(modular.add(p));
    }
    BOOST_TEST(modular.rank() <= exact.rank());  // never above: a lower bound
    BOOST_TEST(modular.rank() == exact.rank());  // and equal for small integers (p ≫ any minor)
  }
}

BOOST_AUTO_TEST_CASE(reduction_mod_prime) {
  const auto p = modular_echelon::prime;
  BOOST_TEST(*reduce_mod_prime(cln::cl_RA(-1)) == p - 1);
  BOOST_TEST(*reduce_mod_prime(cln::cl_RA(1) / 2) == (p + 1) / 2);
  BOOST_TEST(!reduce_mod_prime(cln::cl_RA(1) / cln::cl_I(p)).has_value());
}

BOOST_AUTO_TEST_CASE(orders_outside_the_supported_range_are_refused) {
  BOOST_CHECK_THROW(lie_poisson_algebra(0), std::invalid_argument);
  BOOST_CHECK_THROW(lie_poisson_algebra(max_supported_order + 1), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // lie_poisson_algebra_test
