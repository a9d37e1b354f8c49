// Modular algorithms for univariate polynomials over Q: a square-free certificate modulo one prime,
// and the gcd by images modulo word-size primes: the monic gcd modulo each prime, Chinese
// remaindering of primes whose image has the smallest degree seen, rational reconstruction, and
// exact trial division as the proof. A candidate G that divides a and b over Q
// and has the degree of a modular image (an upper bound on the true degree) is the gcd.
#include <cln/integer.h>

#include <cstdint>
#include <optional>
#include <stdexcept>

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {
namespace {

__extension__ typedef unsigned __int128 wide_uint;
using word = std::uint64_t;

word mul(word a, word b, word p) { return static_cast<word>(static_cast<wide_uint>(a) * b % p); }
word power(word a, word e, word p) {
  word r = 1;
  for (; e; e >>= 1, a = mul(a, a, p))
    if (e & 1) r = mul(r, a, p);
  return r;
}

// Deterministic Miller–Rabin for 64-bit integers (these twelve bases suffice below 3.3·10^24).
bool is_prime(word n) {
  if (n < 2) return false;
  for (word q : {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37})
    if (n % q == 0) return n == q;
  word d = n - 1;
  int s = 0;
  while (d % 2 == 0) d /= 2, ++s;
  for (word a : {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37}) {
    word x = power(a, d, n);
    if (x == 1 || x == n - 1) continue;
    bool composite = true;
    for (int r = 1; r < s && composite; ++r) {
      x = mul(x, x, n);
      if (x == n - 1) composite = false;
    }
    if (composite) return false;
  }
  return true;
}

using modular_poly = std::vector<word>;
void trim(modular_poly& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}
// Monic gcd modulo p (Euclid).
modular_poly gcd_mod(modular_poly a, modular_poly b, word p) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    const word inv = power(b.back(), p - 2, p);
    while (a.size() >= b.size()) {
      const word f = mul(a.back(), inv, p);
      const std::size_t shift = a.size() - b.size();
      for (std::size_t j = 0; j < b.size(); ++j) a[shift + j] = (a[shift + j] + p - mul(f, b[j], p)) % p;
      trim(a);
    }
    std::swap(a, b);
  }
  if (a.empty()) return a;
  const word inv = power(a.back(), p - 2, p);
  for (auto& c : a) c = mul(c, inv, p);
  return a;
}

word residue(const cln::cl_I& x, word p) { return cln::cl_I_to_UQ(cln::mod(x, cln::cl_I(p))); }

// n/d with |n|, d ≤ √(M/2) and n ≡ u d (mod M), if one exists (Wang's rational reconstruction).
std::optional<cln::cl_RA> reconstruct(const cln::cl_I& u, const cln::cl_I& m) {
  const cln::cl_I bound = cln::isqrt(cln::floor1(m, 2));
  cln::cl_I r0 = m, r1 = cln::mod(u, m), t0 = 0, t1 = 1;
  while (r1 > bound) {
    const cln::cl_I q = cln::floor1(r0, r1);
    const cln::cl_I r2 = r0 - q * r1, t2 = t0 - q * t1;
    r0 = r1, r1 = r2, t0 = t1, t1 = t2;
  }
  if (cln::abs(t1) > bound || cln::zerop(t1)) return std::nullopt;
  return cln::cl_RA(r1) / t1;
}

std::vector<cln::cl_I> integer_coefficients(const rational_polynomial& p) {
  cln::cl_I denominators = 1;
  for (const auto& c : p.coefficients()) denominators = cln::lcm(denominators, cln::denominator(c));
  std::vector<cln::cl_I> out;
  for (const auto& c : p.coefficients()) out.push_back(cln::the<cln::cl_I>(c * denominators));
  return out;
}

}  // namespace

// gcd(p, p') = 1 modulo 2^61 − 1 with the degree kept: the discriminant is then nonzero modulo the
// prime, hence nonzero over Q.
bool square_free_certified_mod_prime(const rational_polynomial& p) {
  if (p.degree() < 2) return true;
  constexpr word prime = (word{1} << 61) - 1;
  const auto c = integer_coefficients(p);
  if (residue(c.back(), prime) == 0) return false;  // the prime divides the leading coefficient: no verdict
  modular_poly a, slope;
  for (const auto& x : c) a.push_back(residue(x, prime));
  for (std::size_t i = 1; i < a.size(); ++i) slope.push_back(mul(a[i], i % prime, prime));
  return gcd_mod(a, slope, prime).size() == 1;  // a nonzero constant
}

rational_polynomial modular_gcd(const rational_polynomial& a, const rational_polynomial& b) {
  if (a.is_zero() || b.is_zero()) return gcd(a, b);
  const auto ia = integer_coefficients(a), ib = integer_coefficients(b);
  int best_degree = std::min(a.degree(), b.degree()) + 1;
  std::vector<cln::cl_I> combined;  // coefficients modulo `modulus`
  cln::cl_I modulus = 1;
  int primes_used = 0;
  for (word p = (word{1} << 62) - 1; primes_used < 400; p -= 2) {
    if (!is_prime(p)) continue;
    if (residue(ia.back(), p) == 0 || residue(ib.back(), p) == 0) continue;  // the degrees must survive
    ++primes_used;
    modular_poly ma, mb;
    for (const auto& c : ia) ma.push_back(residue(c, p));
    for (const auto& c : ib) mb.push_back(residue(c, p));
    const modular_poly g = gcd_mod(ma, mb, p);
    const int degree = static_cast<int>(g.size()) - 1;
    if (degree == 0) return rational_polynomial({1});  // coprime modulo p, hence over Q
    if (degree > best_degree) continue;                  // an unlucky prime
    if (degree < best_degree) {                          // every earlier prime was unlucky
      best_degree = degree;
      combined.assign(g.begin(), g.end());
      for (std::size_t i = 0; i < g.size(); ++i) combined[i] = cln::cl_I(g[i]);
      modulus = cln::cl_I(p);
    } else {
      const word inverse = power(residue(modulus, p), p - 2, p);
      for (std::size_t i = 0; i < g.size(); ++i) {
        const word t = mul((g[i] + p - residue(combined[i], p)) % p, inverse, p);
        combined[i] = combined[i] + modulus * cln::cl_I(t);
      }
      modulus = modulus * cln::cl_I(p);
    }
    std::vector<cln::cl_RA> candidate;
    for (const auto& c : combined) {
      const auto r = reconstruct(c, modulus);
      if (!r) break;
      candidate.push_back(*r);
    }
    if (candidate.size() != combined.size()) continue;
    const rational_polynomial g_q(std::move(candidate));
    if (remainder(a, g_q).is_zero() && remainder(b, g_q).is_zero()) return g_q;  // the proof
  }
  return gcd(a, b);  // Euclid over Q: slow but certain
}

}  // namespace rotlie::solver
