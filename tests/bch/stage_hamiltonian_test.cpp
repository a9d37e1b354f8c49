// The symbolic remainders of long words (bch/stage_hamiltonian): against the GiNaC expansion at orders
// 5 and 7 on short words, both evaluated at random rational stage coefficients; Theorems 1 and 2 as
// polynomial identities on a 13-stage palindrome's H_R7; vanishing even orders; the ring's arithmetic
// against exact rationals; refusals.
#include <boost/test/unit_test.hpp>

#include <random>
#include <set>

#include "../support/random_seed.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/stage_hamiltonian.hpp"
#include "rotlie/lie/theorems.hpp"

BOOST_AUTO_TEST_SUITE(stage_hamiltonian_test)

using namespace rotlie;

namespace {

cln::cl_RA random_rational(std::mt19937_64& rng) {
  std::uniform_int_distribution<long> num(-999, 999), den(1, 97);
  return cln::cl_RA(num(rng)) / den(rng);
}

const std::array<cln::cl_RA, 3> water_w{cln::cl_RA(29376) / 10220, cln::cl_RA(29376) / 19187, cln::cl_RA(1)};

// H_Rk from both paths at the same random point: every monomial's coefficient equal, exactly.
void compare_with_ginac(const std::string& word, bch::splitting split, const std::string& perm, int order,
                        std::mt19937_64& rng) {
  const auto layout = bch::layout_scheme(word, split, perm);
  const auto fast = bch::compute_stage_hamiltonian(layout, water_w, order);
  const auto symbols = bch::make_coefficients(layout);
  const bch::inverse_inertia w{GiNaC::numeric(cln::cl_N(water_w[0])), GiNaC::numeric(cln::cl_N(water_w[1])),
                               GiNaC::numeric(cln::cl_N(water_w[2]))};
  const auto slow = bch::compute_modified_hamiltonian(bch::stage_elements(layout, symbols, w), order);
  std::vector<cln::cl_RA> x;
  GiNaC::lst at;
  for (const auto& name : layout.free_coefficients) {
    x.push_back(random_rational(rng));
    at.append(symbols.free.at(name) == GiNaC::numeric(cln::cl_N(x.back())));
  }
  for (int k = 1; k <= order; ++k) {
    const auto& f = fast.remainder[static_cast<std::size_t>(k)];
    const auto& s = slow.remainder[static_cast<std::size_t>(k)];
    std::set<lie::monomial> monomials;
    for (const auto& [m, c] : f.terms()) monomials.insert(m);
    for (const auto& [m, c] : s.terms()) monomials.insert(m);
    for (const auto& m : monomials) {
      const cln::cl_RA a = f.coefficient(m)(x);
      const GiNaC::ex b = s.coefficient(m).subs(at).expand();
      BOOST_REQUIRE(GiNaC::is_a<GiNaC::numeric>(b));
      BOOST_TEST((a == cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(b).to_cl_N())),
                 word << " " << perm << " H_R" << k << " at " << lie::to_string(m));
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(ring_arithmetic_against_rationals) {
  std::mt19937_64 rng(test::test_seed("ring_arithmetic_against_rationals"));
  using P = lie::multivariate_polynomial;
  for (int trial = 0; trial < 20; ++trial) {
    P a = P(random_rational(rng)), b = P(random_rational(rng));
    for (int k = 0; k < 12; ++k) {
      a += P::unknown(k % 11) * P(random_rational(rng));
      b -= P::unknown((3 * k) % 11) * P::unknown(k % 5) * P(random_rational(rng));
    }
    const P c = (a * b + a) * a - b;
    std::vector<cln::cl_RA> x;
    for (int k = 0; k < 11; ++k) x.push_back(random_rational(rng));
    const cln::cl_RA av = a(x), bv = b(x);
    BOOST_TEST((c(x) == (av * bv + av) * av - bv));
    BOOST_TEST((a * b == b * a));
    BOOST_TEST((a - a).is_zero());
  }
  BOOST_CHECK_THROW(P::unknown(16), std::invalid_argument);
  P high = P::unknown(0);
  for (int k = 1; k < 15; ++k) high = high * P::unknown(k % 16);
  BOOST_CHECK_THROW(high * P::unknown(3) * P::unknown(4), std::overflow_error);  // total degree 16
}

BOOST_AUTO_TEST_CASE(orders_5_and_7_match_the_ginac_expansion) {
  std::mt19937_64 rng(test::test_seed("orders_5_and_7_match_the_ginac_expansion"));
  compare_with_ginac("ABCBABCBA", bch::splitting::abc, "BAC", 7, rng);     // N6, 2 free
  compare_with_ginac("RSRSRSRSR", bch::splitting::rs, "CBA", 7, rng);      // R, 3 free
  compare_with_ginac("ABABACABABA", bch::splitting::abc, "ACB", 5, rng);   // P1, 3 free
  compare_with_ginac("ABCABACBCAB", bch::splitting::abc, "ABC", 5, rng);   // not a palindrome: 8 free
}

BOOST_AUTO_TEST_CASE(theorems_1_and_2_hold_identically_at_order_7) {
  // A 13-stage palindrome (4 free coefficients): H_R7 lies on Theorem 1's monomials and its pairing
  // (28) vanishes as a polynomial; the even orders vanish identically.
  const auto layout = bch::layout_scheme("ABCACBABCACBA", bch::splitting::abc, "CAB");
  const auto k = bch::compute_stage_hamiltonian(layout, water_w, 7);
  BOOST_TEST(layout.free_coefficients.size() == 4u);
  for (int even : {2, 4, 6}) BOOST_TEST(k.remainder[static_cast<std::size_t>(even)].is_zero());
  for (int odd : {3, 5, 7}) {
    lie::multivariate_polynomial pairing;
    for (const auto& [m, c] : k.remainder[static_cast<std::size_t>(odd)].terms()) {
      BOOST_TEST(lie::theorem1_allows(odd, m), lie::to_string(m));
      pairing += c * lie::multivariate_polynomial(cln::cl_RA(lie::theorem2_weight(m)));
    }
    BOOST_TEST(pairing.is_zero(), "order " << odd);
    BOOST_TEST(!k.remainder[static_cast<std::size_t>(odd)].is_zero());
  }
  BOOST_TEST(k.remainder[7].size() == lie::theorem1_monomials(7).size());
}

BOOST_AUTO_TEST_CASE(refusals) {
  const auto layout = bch::layout_scheme("ABCBA", bch::splitting::abc);
  BOOST_CHECK_THROW(bch::compute_stage_hamiltonian(layout, water_w, 0), std::invalid_argument);
  BOOST_CHECK_THROW(bch::compute_stage_hamiltonian(layout, water_w, bch::max_remainder_order + 1), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // stage_hamiltonian_test
