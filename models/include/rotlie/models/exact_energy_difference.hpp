#pragma once
// D_y = Σ G_i² (I_i − I_y)/I_i = L² − 2E I_y, the one energy difference whose terms have both signs:
// it vanishes on the separatrix, and summed in floating point its error is ε Σ|terms|, i.e. relative
// ε/δ at a distance δ from the separatrix away from the middle axis. Here it is exact up to one final
// rounding: with I_x, I_z the other two moments,
//   D_y I_x I_z = G_x² I_z (I_x − I_y) + G_z² I_x (I_z − I_y)
// is split by error-free transformations (TwoSum, TwoProduct by fma) into at most 32 floating-point
// numbers whose exact sum it is, and those are summed exactly (Shewchuk's non-overlapping partials)
// when double-S arithmetic (cheap, branch-free) cannot vouch for the last place.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace rotlie::models::detail {

template <class S>
struct exact_sum {
  // non-overlapping partials of increasing magnitude; their exact sum is the sum of everything added
  std::array<S, 48> partials{};
  std::size_t size = 0;

  void add(S x) {
    using std::abs;
    std::size_t kept = 0;
    for (std::size_t j = 0; j < size; ++j) {
      S y = partials[j];
      if (abs(x) < abs(y)) std::swap(x, y);
      const S hi = x + y, lo = y - (hi - x);  // FastTwoSum, |x| ≥ |y|
      if (lo != 0) partials[kept++] = lo;
      x = hi;
    }
    if (kept < partials.size()) {
      partials[kept++] = x;
    } else {
      partials[kept - 1] += x;  // beyond any exponent range reachable here; keeps a rounded sum
    }
    size = kept;
  }

  // the exact sum rounded (faithfully) to S
  S value() const {
    if (size == 0) return S(0);
    S hi = partials[size - 1];
    for (std::size_t j = size - 1; j-- > 0;) {
      const S x = hi, y = partials[j];
      hi = x + y;
      if (y - (hi - x) != 0) break;
    }
    return hi;
  }
};

// a·b·c·(d − e) added exactly to `sum` (products of an expansion by numbers, each by TwoProduct)
template <class S>
void add_exact_product(exact_sum<S>& sum, const S& a, const S& b, const S& c, const S& d, const S& e) {
  using std::fma;
  const S p = a * b, q = fma(a, b, -p);  // a b = p + q
  const S dh = d - e, dz = dh - d, dl = (d - (dh - dz)) + (-e - dz);  // d − e = dh + dl (TwoSum)
  const std::array<S, 2> ab{p, q}, diff{dh, dl};
  for (const S& u : ab) {
    if (u == 0) continue;
    const S h = u * c, l = fma(u, c, -h);
    for (const S& v : {h, l}) {
      if (v == 0) continue;
      for (const S& w : diff) {
        if (w == 0) continue;
        const S r = v * w;
        sum.add(r);
        const S rl = fma(v, w, -r);
        if (rl != 0) sum.add(rl);
      }
    }
  }
}

// a·b·c·(d − e) in double-S: hi + lo with |error| ≤ ~6ε² |a b c (d − e)|, without branches
template <class S>
[[gnu::always_inline]] inline std::pair<S, S> product_pair(const S& a, const S& b, const S& c, const S& d, const S& e) {
  using std::fma;
  const S p = a * b, q = fma(a, b, -p);
  const S dh = d - e, dz = dh - d, dl = (d - (dh - dz)) + (-e - dz);
  const S h = p * c, l = fma(p, c, -h) + q * c;
  const S H = h * dh;
  return {H, fma(h, dh, -H) + (h * dl + l * dh)};
}

/// D_y = L² − 2E I_y for moments I (any order) and the middle index y, correct to a few units of
/// the last place of S for any finite inputs whose products neither overflow nor underflow.
/// Double-S arithmetic first (error ~ε² of the terms: enough unless they cancel to 64ε of
/// themselves), the exact sum only then.
/// `inexact` is set when the terms' sum is so small (< 64 × least normal) that the parts of their
/// products lost to underflow (≤ the least subnormal each, and only for products below
/// least normal / ε⁴) may reach its last place.
template <class S, class V>
S middle_energy_difference(const V& I, const V& G, std::size_t x, std::size_t y, std::size_t z, bool& inexact) {
  using std::abs;
  const auto [ah, al] = product_pair<S>(G[x], G[x], I[z], I[x], I[y]);
  const auto [bh, bl] = product_pair<S>(G[z], G[z], I[x], I[z], I[y]);
  const S sh = ah + bh, sz = sh - ah, sl = (ah - (sh - sz)) + (bh - sz);  // TwoSum
  S E = sh + (sl + al + bl);
  if (!(abs(E) >= 64 * std::numeric_limits<S>::epsilon() * (abs(ah) + abs(bh)))) {
    exact_sum<S> sum;
    add_exact_product(sum, G[x], G[x], I[z], I[x], I[y]);
    add_exact_product(sum, G[z], G[z], I[x], I[z], I[y]);
    E = sum.value();
  }
  // Parts of the products can be lost to underflow only when the products themselves are below
  // least normal / ε⁴ (their exact expansions reach ε⁴ of their size); an exact zero (the
  // separatrix) from products above that is exact.
  const S eps = std::numeric_limits<S>::epsilon(), lossy = std::numeric_limits<S>::min() / (eps * eps * eps * eps);
  inexact = (ah != 0 || bh != 0) && std::max(abs(ah), abs(bh)) < lossy && abs(E) < 64 * std::numeric_limits<S>::min();
  return E / (I[x] * I[z]);
}

}  // namespace rotlie::models::detail
