// Modified Hamiltonians: structure (62) and reduction formula (63) of H_R5 for every N, R and P
// scheme; section 3.1.2 (RSRSRSR with G1²/(2I1) and G3²/(2I3) exchanged has the remainder of
// SRSRSRS) to order 7; first-order consistency; refusals.
#include <boost/test/unit_test.hpp>

#include <array>
#include <map>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/poisson_bracket.hpp"
#include "rotlie/lie/theorems.hpp"

BOOST_AUTO_TEST_SUITE(modified_hamiltonian_test)

using namespace rotlie;
using GiNaC::ex;

namespace {

bch::modified_hamiltonian symbolic_k(std::string_view word, bch::splitting split, const std::string& perm, int order,
                                    bch::coefficient_symbols* coefficients = nullptr) {
  const auto layout = bch::layout_scheme(word, split, perm);
  const auto c = bch::make_coefficients(layout);
  if (coefficients) *coefficients = c;
  return bch::compute_modified_hamiltonian(bch::stage_elements(layout, c, bch::inverse_inertia::symbolic()), order);
}

}  // namespace

BOOST_AUTO_TEST_CASE(h_r5_structure_eqs_62_63_for_every_scheme) {
  for (const auto& s : bch::named_schemes()) {
    const auto k = symbolic_k(s.word, s.split, "ABC", 5);
    BOOST_TEST_CONTEXT(s.name) {
      // first order: H itself, because the first-order conditions hold
      const auto H = bch::part_hamiltonian('A', bch::splitting::abc, "ABC", bch::inverse_inertia::symbolic()) +
                     bch::part_hamiltonian('B', bch::splitting::abc, "ABC", bch::inverse_inertia::symbolic()) +
                     bch::part_hamiltonian('C', bch::splitting::abc, "ABC", bch::inverse_inertia::symbolic());
      BOOST_TEST((k.remainder[1] == H));
      BOOST_TEST(k.remainder[2].is_zero());
      BOOST_TEST(k.remainder[4].is_zero());
      BOOST_TEST(!k.remainder[3].is_zero());
      ex pairing = 0;
      for (const auto& [m, c] : k.remainder[5].terms()) {
        BOOST_TEST(lie::theorem1_allows(5, m), lie::to_string(m));  // one of the 7 monomials of (62)
        pairing += GiNaC::numeric(cln::cl_N(lie::theorem2_weight(m))) * c;
      }
      BOOST_TEST(pairing.expand().is_zero());  // 3(Q1 + … + Q6) + Q7 = 0, eq. (63)
      BOOST_TEST(k.remainder[5].size() == 7u);
    }
  }
}

BOOST_AUTO_TEST_CASE(section_3_1_2_exchange_to_order_7) {
  // RSRSRSR with axes 1 and 3 exchanged (permutation CBA) against SRSRSRS.
  bch::coefficient_symbols c1, c2;
  const auto swapped = symbolic_k("RSRSRSR", bch::splitting::rs, "CBA", 7, &c1);
  const auto srs = symbolic_k("SRSRSRS", bch::splitting::rs, "ABC", 7, &c2);
  // Same coefficient names (a1, b1) but distinct symbols: identify them.
  GiNaC::lst same;
  for (const auto& [name, sym] : c1.free) same.append(sym == c2.free.at(name));
  for (int order = 2; order <= 7; ++order) {
    const auto& a = swapped.remainder[static_cast<std::size_t>(order)];
    const auto& b = srs.remainder[static_cast<std::size_t>(order)];
    BOOST_TEST(a.size() == b.size(), "order " << order);
    for (const auto& [m, c] : a.terms())
      BOOST_TEST((c.subs(same) - b.coefficient(m)).expand().is_zero(), "order " << order << " " << lie::to_string(m));
  }
  BOOST_TEST(!srs.remainder[7].is_zero());
}

BOOST_AUTO_TEST_CASE(casimir_part_commutes_with_r1_and_r3) {
  const auto w = bch::inverse_inertia::symbolic();
  const auto R = bch::part_hamiltonian('R', bch::splitting::rs, "ABC", w);
  const auto S = bch::part_hamiltonian('S', bch::splitting::rs, "ABC", w);
  const auto R3 = bch::part_hamiltonian('R', bch::splitting::rs, "CBA", w);  // G3²/2 (1/I3 − 1/I2)
  const auto RG = S - R3;                                                     // G²/(2I2)
  BOOST_TEST(lie::poisson_bracket(RG, R).is_zero());
  BOOST_TEST(lie::poisson_bracket(RG, R3).is_zero());
  // and R + S = H (eqs. 7–9)
  const auto H = bch::part_hamiltonian('A', bch::splitting::abc, "ABC", w) +
                 bch::part_hamiltonian('B', bch::splitting::abc, "ABC", w) +
                 bch::part_hamiltonian('C', bch::splitting::abc, "ABC", w);
  BOOST_TEST(((R + S) == H));
}

BOOST_AUTO_TEST_CASE(non_symmetric_words_get_even_orders) {
  // Lie–Trotter ABC: H_R2 = ½({A,B} + {A,C} + {B,C}) ≠ 0.
  const auto k = symbolic_k("ABC", bch::splitting::abc, "ABC", 3);
  BOOST_TEST(!k.remainder[2].is_zero());
  const auto w = bch::inverse_inertia::symbolic();
  const auto A = bch::part_hamiltonian('A', bch::splitting::abc, "ABC", w);
  const auto B = bch::part_hamiltonian('B', bch::splitting::abc, "ABC", w);
  const auto C = bch::part_hamiltonian('C', bch::splitting::abc, "ABC", w);
  auto half = lie::poisson_bracket(A, B) + lie::poisson_bracket(A, C) + lie::poisson_bracket(B, C);
  half *= ex(GiNaC::numeric(1, 2));
  BOOST_TEST((k.remainder[2] == half));
}

BOOST_AUTO_TEST_CASE(orders_outside_the_range_are_refused) {
  const auto layout = bch::layout_scheme("ABCBA", bch::splitting::abc);
  const auto st = bch::stage_elements(layout, bch::make_coefficients(layout), bch::inverse_inertia::symbolic());
  BOOST_CHECK_THROW(bch::compute_modified_hamiltonian(st, 0), std::invalid_argument);
  BOOST_CHECK_THROW(bch::compute_modified_hamiltonian(st, bch::max_remainder_order + 1), std::invalid_argument);
  BOOST_CHECK_THROW(bch::compute_modified_hamiltonian({}, 3), std::invalid_argument);
}

// The exact path (coefficient_polynomial, no GiNaC) against the GiNaC path, coefficient by
// coefficient, for every named scheme in two permutations, on water's rational moments.
BOOST_AUTO_TEST_CASE(exact_path_equals_the_ginac_path) {
  const std::array<cln::cl_RA, 3> w{cln::cl_RA(29376) / 10220, cln::cl_RA(29376) / 19187, 1};
  const bch::inverse_inertia wg{GiNaC::numeric(cln::cl_N(w[0])), GiNaC::numeric(cln::cl_N(w[1])), GiNaC::numeric(cln::cl_N(w[2]))};
  for (const auto& s : bch::named_schemes())
    for (const std::string perm : {"ABC", "CAB"}) {
      const auto layout = bch::layout_scheme(s.word, s.split, perm);
      const auto c = bch::make_coefficients(layout);
      const auto symbolic = bch::compute_modified_hamiltonian(bch::stage_elements(layout, c, wg), 5);
      const auto exact = bch::compute_exact_modified_hamiltonian(layout, w, 5);
      BOOST_TEST_CONTEXT(std::string(s.name) + " " + perm) {
        BOOST_REQUIRE(exact.unknowns == layout.free_coefficients);
        for (int order = 1; order <= 5; ++order) {
          BOOST_TEST(exact.remainder[static_cast<std::size_t>(order)].size() ==
                     symbolic.remainder[static_cast<std::size_t>(order)].size());
          for (const auto& [m, q] : symbolic.remainder[static_cast<std::size_t>(order)].terms()) {
            ex converted = 0;
            const auto coefficient = exact.remainder[static_cast<std::size_t>(order)].coefficient(m);
            for (const auto& t : coefficient.terms()) {
              const auto e = lie::coefficient_polynomial::unpack(t.key);
              ex term = GiNaC::numeric(cln::cl_N(t.c));
              for (std::size_t k = 0; k < exact.unknowns.size(); ++k) term *= GiNaC::pow(c.free.at(exact.unknowns[k]), e[k]);
              converted += term;
            }
            BOOST_TEST((converted - q).expand().is_zero(), "order " << order << " " << lie::to_string(m));
          }
        }
      }
    }
}

// The double-precision path at a numeric point equals the exact path evaluated there.
BOOST_AUTO_TEST_CASE(numeric_path_equals_the_exact_path_at_a_point) {
  const std::array<cln::cl_RA, 3> w{cln::cl_RA(29376) / 10220, cln::cl_RA(29376) / 19187, 1};
  for (const std::string name : {"N2", "P1", "R"}) {
    const auto s = *bch::find_named_scheme(name);
    const auto layout = bch::layout_scheme(s.word, s.split, "BAC");
    const auto exact = bch::compute_exact_modified_hamiltonian(layout, w, 5);
    std::vector<double> x;
    for (std::size_t k = 0; k < exact.unknowns.size(); ++k) x.push_back(0.1 + 0.07 * static_cast<double>(k));
    std::map<std::string, double> values;
    for (const auto& [coefficient, expression] : exact.coefficient_values) values[coefficient] = expression.evaluate(x);
    const auto numeric = bch::compute_numeric_modified_hamiltonian(layout, w, values, 5);
    for (const auto& [m, q] : exact.remainder[5].terms())
      BOOST_TEST(numeric[5].coefficient(m) == q.evaluate(x), boost::test_tools::tolerance(1e-11));
  }
}

BOOST_AUTO_TEST_SUITE_END()  // modified_hamiltonian_test
