#pragma once
// Shared by the bch tests: the third-order coefficients P'_1, P'_2, P'_3 of eq. (21)/(47)/(58)
// of a scheme, in the paper's variables (x, y) and scaled by (2I1)³.
#include "rotlie/bch/modified_hamiltonian.hpp"

namespace rotlie::test {

struct third_order {
  GiNaC::symbol x{"x"}, y{"y"};
  bch::coefficient_symbols coefficients;
  GiNaC::ex p1, p2, p3;  // of G1²G2², G1²G3², G2²G3²
  bch::modified_hamiltonian k;
};

inline third_order paper_third_order(const std::string& word, bch::splitting split, const std::string& perm = "ABC",
                                     int order = 3) {
  third_order t;
  const auto layout = bch::layout_scheme(word, split, perm);
  t.coefficients = bch::make_coefficients(layout);
  const auto w = split == bch::splitting::abc ? bch::inverse_inertia::abc_paper(t.x, t.y)
                                              : bch::inverse_inertia::rs_paper(t.x, t.y);
  t.k = bch::compute_modified_hamiltonian(bch::stage_elements(layout, t.coefficients, w), order);
  const auto& h3 = t.k.remainder[3];
  t.p1 = h3.coefficient(lie::monomial(2, 2, 0));
  t.p2 = h3.coefficient(lie::monomial(2, 0, 2));
  t.p3 = h3.coefficient(lie::monomial(0, 2, 2));
  return t;
}

inline bool same(const GiNaC::ex& a, const GiNaC::ex& b) { return (a - b).expand().is_zero(); }

/// Exact: prem(p, f, v) = 0, i.e. f divides p (up to a factor free of v).
inline bool divides(const GiNaC::ex& f, const GiNaC::ex& p, const GiNaC::symbol& v) {
  return GiNaC::prem(p.expand(), f.expand(), v).expand().is_zero();
}

/// Checks an elimination of the form f(v1) = 0, g = g0 + v2·g1 + (terms in v1) = 0 against the engine's
/// P'_1 = P'_2 = 0: (i) every root of f with v2 from g solves both, (ii) f divides Res_v2(P'_1, P'_2).
/// Needs Boost.Test included before this header.
inline void check_elimination(const third_order& t, const std::string& v1_name, const std::string& v2_name,
                              const GiNaC::ex& f, const GiNaC::ex& g, const std::string& label) {
  const GiNaC::symbol v1 = t.coefficients.free.at(v1_name), v2 = t.coefficients.free.at(v2_name);
  const GiNaC::ex g1 = g.expand().coeff(v2, 1), rest = (g - v2 * g1).expand();
  BOOST_REQUIRE(!g1.is_zero());
  for (const GiNaC::ex& p : {t.p1, t.p2}) {
    const GiNaC::ex substituted = GiNaC::numer(GiNaC::normal(p.subs(v2 == -rest / g1)));
    BOOST_TEST(divides(f, substituted, v1), label << ": f(" << v1_name << ") = 0 with g = 0 solves P' = 0");
  }
  const GiNaC::ex res = GiNaC::resultant(t.p1.expand(), t.p2.expand(), v2);
  BOOST_TEST(divides(f, res, v1), label << ": f divides the resultant");
  BOOST_TEST_MESSAGE(label << ": Res_" << v2_name << "(P'_1, P'_2) = f × "
                           << GiNaC::factor(GiNaC::quo(res.expand(), f.expand(), v1)));
}

}  // namespace rotlie::test
