#include "rotlie/lie/modular_rank.hpp"

#include <cln/integer.h>

namespace rotlie::lie {
namespace {

constexpr std::uint64_t p = modular_echelon::prime;
__extension__ typedef unsigned __int128 wide_uint;

std::uint64_t mul_mod(std::uint64_t a, std::uint64_t b) {
  return static_cast<std::uint64_t>((static_cast<wide_uint>(a) * b) % p);
}
std::uint64_t sub_mod(std::uint64_t a, std::uint64_t b) { return a >= b ? a - b : a + p - b; }
std::uint64_t inverse_mod(std::uint64_t a) {  // Fermat: a^(p−2)
  std::uint64_t result = 1, base = a, e = p - 2;
  while (e) {
    if (e & 1) result = mul_mod(result, base);
    base = mul_mod(base, base);
    e >>= 1;
  }
  return result;
}
std::uint64_t integer_mod(const cln::cl_I& x) { return cln::cl_I_to_UQ(cln::mod(x, cln::cl_I(p))); }

}  // namespace

std::optional<std::uint64_t> reduce_mod_prime(const cln::cl_RA& x) {
  const std::uint64_t den = integer_mod(cln::denominator(x));
  if (den == 0) return std::nullopt;
  return mul_mod(integer_mod(cln::numerator(x)), inverse_mod(den));
}

bool modular_echelon::add(const polynomial<cln::cl_RA>& v) {
  row r;
  for (const auto& [m, c] : v.terms()) {
    const auto x = reduce_mod_prime(c);
    if (!x) return false;
    if (*x) r.emplace(m, *x);
  }
  while (!r.empty()) {
    const auto lead = r.rbegin();
    const auto pivot = pivots_.find(lead->first);
    if (pivot == pivots_.end()) {
      const std::uint64_t inv = inverse_mod(lead->second);
      for (auto& [m, c] : r) c = mul_mod(c, inv);
      const monomial key = lead->first;
      pivots_.emplace(key, std::move(r));
      return true;
    }
    const std::uint64_t factor = lead->second;
    for (const auto& [m, c] : pivot->second) {
      ++operations_;
      auto [it, inserted] = r.try_emplace(m, 0);
      it->second = sub_mod(it->second, mul_mod(factor, c));
      if (it->second == 0) r.erase(it);
    }
  }
  return true;
}

}  // namespace rotlie::lie
