#pragma once
// Random numbers that are the same for a seed on every IEEE-754 machine and with every compiler:
// xoshiro256** (Blackman & Vigna 2018) seeded through splitmix64, uniforms from the top 53 bits,
// and normals by Marsaglia's polar method with a logarithm written here in basic operations
// only (the C library's log may differ in the last bit between platforms; std::normal_distribution
// is not specified at all). Each run of an ensemble has its own stream, derived from (seed, run),
// so run r draws the same numbers whatever the ensemble size. (Targets that fuse a·b + c into one
// FMA by default must build with -ffp-contract=off for bit-equality with x86-64.)
#include <cmath>
#include <cstdint>

namespace rotlie::models {

/// splitmix64 (Steele, Lea & Flood 2014): a seed and a stream index scrambled into 64 bits.
constexpr std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace detail {
/// ln x for finite x > 0 from +, −, ×, / and exact scalings only: x = m·2^e with m in [√½, √2),
/// ln m = 2 atanh(s), s = (m − 1)/(m + 1), |s| ≤ 0.172, the series summed to 2^-60.
inline double portable_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // exact: m in [½, 1)
  if (m < 0.70710678118654752) m *= 2, e -= 1;
  const double s = (m - 1) / (m + 1), s2 = s * s;
  double term = s, sum = 0;
  for (int k = 1; k < 60 && term != 0; k += 2) {
    sum += term / k;
    term *= s2;
  }
  constexpr double ln2_hi = 0.693147180369123816490, ln2_lo = 1.90821492927058770002e-10;  // ln 2 = hi + lo
  return (e * ln2_hi + 2 * sum) + e * ln2_lo;
}
}  // namespace detail

class seeded_random {
 public:
  /// The stream of run `run` of the ensemble with seed `seed`.
  seeded_random(std::uint64_t seed, std::uint64_t run = 0) {
    std::uint64_t x = seed ^ splitmix64(run);
    for (auto& w : s_) w = splitmix64(x);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Standard normal (Marsaglia's polar method; the second value of each pair is kept for the next call).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0, v = 0, r = 0;
    do {
      u = 2 * uniform() - 1;
      v = 2 * uniform() - 1;
      r = u * u + v * v;
    } while (r >= 1 || r == 0);
    const double f = std::sqrt(-2 * detail::portable_log(r) / r);  // sqrt is correctly rounded by IEEE-754
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4]{};
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace rotlie::models
