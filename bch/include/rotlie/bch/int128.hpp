#pragma once
// 128-bit integers for exact series coefficients over a common denominator: the product of two
// 64-bit numbers fits, and every operation whose operands are not bounded in advance is checked.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rotlie::bch {

__extension__ using int128 = __int128;
__extension__ using uint128 = unsigned __int128;

/// a + b, a − b, a · b that throw std::overflow_error instead of wrapping.
inline int128 checked_add(int128 a, int128 b) {
  int128 r;
  if (__builtin_add_overflow(a, b, &r)) throw std::overflow_error("128-bit overflow in a series coefficient");
  return r;
}
inline int128 checked_sub(int128 a, int128 b) {
  int128 r;
  if (__builtin_sub_overflow(a, b, &r)) throw std::overflow_error("128-bit overflow in a series coefficient");
  return r;
}
inline int128 checked_mul(int128 a, int128 b) {
  int128 r;
  if (__builtin_mul_overflow(a, b, &r)) throw std::overflow_error("128-bit overflow in a series coefficient");
  return r;
}

inline uint128 magnitude(int128 a) { return a < 0 ? uint128(0) - static_cast<uint128>(a) : static_cast<uint128>(a); }

inline int128 gcd(int128 a, int128 b) {
  uint128 x = magnitude(a), y = magnitude(b);
  while (y != 0) {
    const uint128 t = x % y;
    x = y;
    y = t;
  }
  return static_cast<int128>(x);
}

inline std::string to_string(int128 a) {
  uint128 m = magnitude(a);
  std::string digits;
  do {
    digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(m % 10)));
    m /= 10;
  } while (m != 0);
  return a < 0 ? "-" + digits : digits;
}

/// "p/q" in lowest terms (q > 0), or "p" when q divides p.
inline std::string fraction_text(int128 numerator, int128 denominator) {
  const int128 g = gcd(numerator, denominator);
  if (g == 0) return "0";
  int128 p = numerator / g, q = denominator / g;
  if (q < 0) p = -p, q = -q;
  return q == 1 ? to_string(p) : to_string(p) + "/" + to_string(q);
}

}  // namespace rotlie::bch
