#include "rotlie/bch/modified_hamiltonian.hpp"

#include <stdexcept>

#include "rotlie/bch/evaluate.hpp"
#include "rotlie/bch/lie_series.hpp"
#include "rotlie/lie/poisson_bracket.hpp"
#include "rotlie/lie/theorems.hpp"

namespace rotlie::bch {
namespace {

// The Lie–Poisson algebra truncated at a maximal order: terms of order > max_order
// (polynomial degree > max_order + 1) are dropped as soon as they appear.
struct truncated_poisson_algebra {
  int max_order;
  symbolic_polynomial bracket(const symbolic_polynomial& a, const symbolic_polynomial& b) const {
    symbolic_polynomial out;
    const auto max_degree = static_cast<std::uint32_t>(max_order + 1);
    for (const auto& [ma, ca] : a.terms())
      for (const auto& [mb, cb] : b.terms()) {
        if (ma.degree() + mb.degree() - 1 > max_degree) continue;  // {deg p, deg q} has degree p + q − 1
        lie::bracket_of_monomials(ma, mb, [&](const lie::monomial& m, long c) { out.add_term(m, c * ca * cb); });
      }
    return out;
  }
  void add_scaled(symbolic_polynomial& acc, const cln::cl_RA& c, const symbolic_polynomial& x) const {
    const GiNaC::ex factor = GiNaC::numeric(cln::cl_N(c));
    for (const auto& [m, v] : x.terms()) acc.add_term(m, factor * v);
  }
  symbolic_polynomial zero() const { return {}; }
};

bool is_palindrome(const std::vector<stage_element>& s) {
  for (std::size_t i = 0; i < s.size() / 2; ++i) {
    const auto& a = s[i];
    const auto& b = s[s.size() - 1 - i];
    if (!(a.coefficient - b.coefficient).expand().is_zero() || !(a.part == b.part)) return false;
  }
  return true;
}

symbolic_polynomial scaled(const stage_element& s) {
  symbolic_polynomial x;
  for (const auto& [m, c] : s.part.terms()) x.add_term(m, s.coefficient * c);
  return x;
}

}  // namespace

inverse_inertia inverse_inertia::symbolic() {
  // GiNaC symbols are equal only to themselves: one set for the whole program.
  static const GiNaC::symbol w1("w1"), w2("w2"), w3("w3");
  return {w1, w2, w3};
}
inverse_inertia inverse_inertia::abc_paper(const GiNaC::symbol& x, const GiNaC::symbol& y) {
  return {2, 2 * (1 + x), 2 * (1 + y)};
}
inverse_inertia inverse_inertia::rs_paper(const GiNaC::symbol& x, const GiNaC::symbol& y) { return {2, 2 * x, 2 * y}; }

symbolic_polynomial part_hamiltonian(char letter, splitting split, const std::string& permutation,
                                     const inverse_inertia& w) {
  auto axis = [&](std::size_t i) { return permutation[i] - 'A' + 1; };
  auto square = [](int i, const GiNaC::ex& c) {
    lie::monomial m;
    m.exponent[static_cast<std::size_t>(i - 1)] = 2;
    return symbolic_polynomial::term(m, c);
  };
  if (split == splitting::abc) {
    if (letter < 'A' || letter > 'C') throw std::invalid_argument("not an ABC part");
    const int i = letter - 'A' + 1;
    return square(i, w[i] / 2);
  }
  const int p1 = axis(0), p2 = axis(1), p3 = axis(2);
  if (letter == 'R') return square(p1, (w[p1] - w[p2]) / 2);
  if (letter == 'S') return square(p3, (w[p3] - w[p2]) / 2) + square(1, w[p2] / 2) + square(2, w[p2] / 2) + square(3, w[p2] / 2);
  throw std::invalid_argument("not an RS part");
}

modified_hamiltonian compute_modified_hamiltonian(const std::vector<stage_element>& stages, int max_order) {
  if (max_order < 1 || max_order > max_remainder_order)
    throw std::invalid_argument("the order must be between 1 and " + std::to_string(max_remainder_order));
  if (stages.empty()) throw std::invalid_argument("a scheme needs at least one stage");
  const truncated_poisson_algebra algebra{max_order};
  symbolic_polynomial z;
  if (is_palindrome(stages)) {
    // log(e^x e^Z e^x) from the middle stage outwards.
    const auto series = symmetric_bch_series(max_order);
    const std::size_t n = stages.size();
    z = scaled(stages[n / 2]);
    for (std::size_t i = n / 2; i-- > 0;)
      z = evaluate(series, std::vector<symbolic_polynomial>{scaled(stages[i]), z}, algebra, max_order);
  } else {
    const auto series = bch_series(max_order);
    z = scaled(stages.front());
    for (std::size_t i = 1; i < stages.size(); ++i)
      z = evaluate(series, std::vector<symbolic_polynomial>{z, scaled(stages[i])}, algebra, max_order);
  }
  modified_hamiltonian k;
  k.max_order = max_order;
  k.remainder.resize(static_cast<std::size_t>(max_order) + 1);
  for (const auto& [m, c] : z.terms()) k.remainder[m.degree() - 1].add_term(m, c);
  return k;
}

GiNaC::ex theorem2_pairing(const symbolic_polynomial& x) {
  GiNaC::ex pairing = 0;
  for (const auto& [m, c] : x.terms()) pairing += GiNaC::numeric(cln::cl_N(lie::theorem2_weight(m))) * c;
  return pairing.expand();
}

std::vector<stage_element> stage_elements(const scheme_layout& layout, const coefficient_symbols& coefficients,
                                          const inverse_inertia& w) {
  std::vector<stage_element> out;
  for (const auto& s : layout.stages)
    out.push_back({coefficients.value.at(s.coefficient), part_hamiltonian(s.letter, layout.split, layout.permutation, w)});
  return out;
}

}  // namespace rotlie::bch
