#pragma once
// 128-bit integers for exact series coefficients over a common denominator: the product of two
// 64-bit numbers fits, and every operation whose operands are not bounded in advance is checked.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

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

/// gcd of two magnitudes: 128-bit remainders only while a number is wider than 64 bits, then
/// binary steps on 64 bits (far cheaper than a 128-bit division).
inline uint128 gcd_of_magnitudes(uint128 x, uint128 y) {
  while ((x >> 64) != 0 || (y >> 64) != 0) {
    if (y == 0) return x;
    const uint128 t = x % y;
    x = y;
    y = t;
  }
  auto a = static_cast<std::uint64_t>(x), b = static_cast<std::uint64_t>(y);
  if (a == 0 || b == 0) return a | b;
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return a << shift;
}

inline int128 gcd(int128 a, int128 b) { return static_cast<int128>(gcd_of_magnitudes(magnitude(a), magnitude(b))); }

/// The decimal digits of m at out; returns the end. At most 39 characters.
inline char* write_decimal(char* out, uint128 m) {
  constexpr std::uint64_t ten19 = 10000000000000000000ull;
  char digits[40];
  char* p = digits + sizeof digits;
  while ((m >> 64) != 0) {  // 19 digits at a time from the low end: one 128-bit division each
    const uint128 q = m / ten19;
    auto r = static_cast<std::uint64_t>(m - q * ten19);
    for (int k = 0; k < 19; ++k, r /= 10) *--p = static_cast<char>('0' + r % 10);
    m = q;
  }
  auto v = static_cast<std::uint64_t>(m);
  do {
    *--p = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  const auto n = static_cast<std::size_t>(digits + sizeof digits - p);
  std::memcpy(out, p, n);
  return out + n;
}

/// a in decimal at out ("-12"); returns the end. At most 40 characters.
inline char* write_integer(char* out, int128 a) {
  if (a < 0) *out++ = '-';
  return write_decimal(out, magnitude(a));
}

/// a / b for b dividing a, on 64 bits when both fit.
inline int128 exact_quotient(int128 a, int128 b) {
  constexpr int128 low = -(int128(1) << 63), high = (int128(1) << 63) - 1;
  if (a >= low && a <= high && b >= low && b <= high && b != -1)
    return static_cast<std::int64_t>(a) / static_cast<std::int64_t>(b);
  return a / b;
}

/// "p/q" in lowest terms (q > 0), or "p" when q divides p, at out; returns the end. At most 81 characters.
inline char* write_fraction(char* out, int128 numerator, int128 denominator) {
  const int128 g = gcd(numerator, denominator);
  if (g == 0) {
    *out++ = '0';
    return out;
  }
  int128 p = g == 1 ? numerator : exact_quotient(numerator, g), q = g == 1 ? denominator : exact_quotient(denominator, g);
  if (q < 0) p = -p, q = -q;
  out = write_integer(out, p);
  if (q == 1) return out;
  *out++ = '/';
  return write_integer(out, q);
}

inline std::string to_string(int128 a) {
  char text[40];
  return std::string(text, write_integer(text, a));
}

/// "p/q" in lowest terms (q > 0), or "p" when q divides p.
inline std::string fraction_text(int128 numerator, int128 denominator) {
  char text[81];
  return std::string(text, write_fraction(text, numerator, denominator));
}

}  // namespace rotlie::bch
