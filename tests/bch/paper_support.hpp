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

}  // namespace rotlie::test
