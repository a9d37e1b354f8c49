// Theorem 1 monomials and counts (section 2.4), Theorem 2 weights (eq. 35) and the bound space V_k.
#include <boost/test/unit_test.hpp>

#include "rotlie/lie/exact_echelon.hpp"
#include "rotlie/lie/theorems.hpp"

BOOST_AUTO_TEST_SUITE(theorems_test)

using namespace rotlie::lie;

BOOST_AUTO_TEST_CASE(monomial_counts_match_section_2_4) {
  BOOST_TEST(theorem1_monomials(1).size() == 3u);
  for (int k = 1; k <= 30; ++k) {
    BOOST_TEST(theorem1_monomials(2 * k).size() == static_cast<std::size_t>(k * (k + 1) / 2), "order " << 2 * k);
    BOOST_TEST(theorem1_monomials(2 * k + 1).size() == static_cast<std::size_t>(k * (k + 5) / 2), "order " << 2 * k + 1);
  }
}

BOOST_AUTO_TEST_CASE(low_order_supports_are_the_papers) {
  // Order 2: W = G1G2G3 (eq. 17). Order 3: G1²G2², G1²G3², G2²G3² (eq. 21).
  BOOST_TEST((theorem1_monomials(2) == std::vector<monomial>{monomial(1, 1, 1)}));
  BOOST_TEST((theorem1_monomials(3) == std::vector<monomial>{monomial(2, 2, 0), monomial(2, 0, 2), monomial(0, 2, 2)}));
  // Order 5: the seven monomials of eq. (62); G1^6 (p = 3 > k = 2) is excluded.
  BOOST_TEST(theorem1_monomials(5).size() == 7u);
  BOOST_TEST(!theorem1_allows(5, monomial(6, 0, 0)));
  BOOST_TEST(!theorem1_allows(5, monomial(2, 2, 1)));
  BOOST_TEST(theorem1_allows(5, monomial(2, 2, 2)));
}

BOOST_AUTO_TEST_CASE(theorem2_weights_are_gaussian_moments) {
  // (2p)!/(2^p p!) = E[x^2p] for a standard normal x: 1, 1, 3, 15, 105, 945.
  const long moments[] = {1, 1, 3, 15, 105, 945};
  for (std::uint32_t p = 0; p < 6; ++p) BOOST_TEST(theorem2_weight(monomial(2 * p, 0, 0)) == moments[p]);
  BOOST_TEST(theorem2_weight(monomial(4, 2, 6)) == 3 * 1 * 15);
}

BOOST_AUTO_TEST_CASE(eq_28_gives_eq_22_at_order_3) {
  // Order 3 has weights 1 on all three monomials, so eq. (28) reads P1 + P2 + P3 = 0 (eq. 22).
  for (const auto& m : theorem1_monomials(3)) BOOST_TEST(theorem2_weight(m) == 1);
  // and eq. (63) at order 5: weight 3 on G_i^4 G_j^2 and 1 on G1²G2²G3².
  for (const auto& m : theorem1_monomials(5))
    BOOST_TEST(theorem2_weight(m) == (m == monomial(2, 2, 2) ? 1 : 3), to_string(m));
}

BOOST_AUTO_TEST_CASE(bound_space_basis_is_independent_and_satisfies_both_theorems) {
  for (int order = 1; order <= 25; ++order) {
    const auto basis = theorem_space_basis(order);
    BOOST_TEST(basis.size() == theorem_bound(order), "order " << order);
    exact_echelon echelon;
    for (const auto& v : basis) {
      BOOST_TEST(echelon.add(v));
      for (const auto& [m, c] : v.terms()) BOOST_TEST(theorem1_allows(order, m));
      if (theorem2_applies(order)) BOOST_TEST(cln::zerop(theorem2_pairing(v)));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()  // theorems_test
