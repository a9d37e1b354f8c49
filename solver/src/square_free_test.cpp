// A cheap certificate that a rational polynomial is square-free: gcd(p, p') = 1 modulo a prime
// that keeps the degree. Then the discriminant is nonzero mod the prime, hence nonzero over Q.
#include <cln/integer.h>

#include <cstdint>

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {
namespace {

constexpr std::uint64_t prime = (std::uint64_t{1} << 61) - 1;
__extension__ typedef unsigned __int128 wide_uint;

std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
  const wide_uint r = static_cast<wide_uint>(a) * b;
  const std::uint64_t lo = static_cast<std::uint64_t>(r & prime), hi = static_cast<std::uint64_t>(r >> 61);
  std::uint64_t s = lo + hi;
  if (s >= prime) s -= prime;
  return s;
}
std::uint64_t sub(std::uint64_t a, std::uint64_t b) { return a >= b ? a - b : a + prime - b; }
std::uint64_t power(std::uint64_t a, std::uint64_t e) {
  std::uint64_t r = 1;
  for (; e; e >>= 1, a = mul(a, a))
    if (e & 1) r = mul(r, a);
  return r;
}
std::uint64_t inverse(std::uint64_t a) { return power(a, prime - 2); }
std::uint64_t reduce(const cln::cl_I& x) {
  const cln::cl_I r = cln::mod(x, cln::cl_I(prime));
  return cln::cl_I_to_UQ(r);
}

using modular_poly = std::vector<std::uint64_t>;
void trim(modular_poly& a) {
  while (!a.empty() && a.back() == 0) a.pop_back();
}
// a ← a mod b (b monic-normalised inside).
void remainder_in_place(modular_poly& a, const modular_poly& b) {
  const std::uint64_t inv = inverse(b.back());
  while (a.size() >= b.size()) {
    const std::uint64_t f = mul(a.back(), inv);
    const std::size_t shift = a.size() - b.size();
    for (std::size_t j = 0; j < b.size(); ++j) a[shift + j] = sub(a[shift + j], mul(f, b[j]));
    trim(a);
  }
}

}  // namespace

bool square_free_certified_mod_prime(const rational_polynomial& p) {
  if (p.degree() < 2) return true;
  cln::cl_I denominators = 1;
  for (const auto& c : p.coefficients()) denominators = cln::lcm(denominators, cln::denominator(c));
  modular_poly a;
  for (const auto& c : p.coefficients()) a.push_back(reduce(cln::the<cln::cl_I>(c * denominators)));
  if (a.back() == 0) return false;  // the prime divides the leading coefficient: no verdict
  modular_poly b;
  for (std::size_t i = 1; i < a.size(); ++i) b.push_back(mul(a[i], i % prime));
  trim(b);
  while (!b.empty()) {
    remainder_in_place(a, b);
    std::swap(a, b);
  }
  return a.size() == 1;  // gcd is a nonzero constant
}

}  // namespace rotlie::solver
