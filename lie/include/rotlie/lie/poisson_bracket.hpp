#pragma once
// The Lie–Poisson bracket of so(3)*:  {f,g} = Σ εijk G_k ∂f/∂G_i ∂g/∂G_j, so {G1,G2} = G3 (eq. 16).
#include "rotlie/lie/polynomial.hpp"

namespace rotlie::lie {

/// The three cyclic index triples (i, j, k) with εijk = +1 (0-based).
inline constexpr int cyclic_triples[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};

/// {G^a, G^b} on monomials directly: for each cyclic (i,j,k),
/// (a_i b_j − a_j b_i) G^(a+b−e_i−e_j+e_k). Calls sink(monomial, integer coefficient).
template <class Sink>
void bracket_of_monomials(const monomial& a, const monomial& b, Sink&& sink) {
  for (const auto& t : cyclic_triples) {
    const auto i = static_cast<std::size_t>(t[0]), j = static_cast<std::size_t>(t[1]),
               k = static_cast<std::size_t>(t[2]);
    const long c = static_cast<long>(a.exponent[i]) * b.exponent[j] - static_cast<long>(a.exponent[j]) * b.exponent[i];
    if (c == 0) continue;  // also guarantees the exponents below do not underflow
    monomial m(a[0] + b[0], a[1] + b[1], a[2] + b[2]);
    m.exponent[i] -= 1;
    m.exponent[j] -= 1;
    m.exponent[k] += 1;
    sink(m, c);
  }
}

template <class R>
polynomial<R> poisson_bracket(const polynomial<R>& f, const polynomial<R>& g) {
  using traits = ring_traits<R>;
  polynomial<R> out;
  for (const auto& [ma, ca] : f.terms())
    for (const auto& [mb, cb] : g.terms())
      // explicit captures: clang before 16 cannot capture structured bindings implicitly
      bracket_of_monomials(ma, mb, [&, &ca = ca, &cb = cb](const monomial& m, long c) {
        out.add_term(m, traits::from_int(c) * ca * cb);
      });
  return out;
}

}  // namespace rotlie::lie
