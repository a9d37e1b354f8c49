#include "rotlie/lie/free_lie_dimension.hpp"

#include <stdexcept>

namespace rotlie::lie {
namespace {
__extension__ typedef __int128 wide_int;  // exact n^k before the division by k
}  // namespace

int moebius(std::uint64_t n) {
  int mu = 1;
  for (std::uint64_t p = 2; p * p <= n; ++p) {
    if (n % p) continue;
    n /= p;
    if (n % p == 0) return 0;  // p² divides n
    mu = -mu;
  }
  return n > 1 ? -mu : mu;
}

std::int64_t free_lie_dimension(int letters, int degree) {
  if (letters < 1 || degree < 1) throw std::invalid_argument("free_lie_dimension needs letters ≥ 1 and degree ≥ 1");
  wide_int sum = 0;
  for (int d = 1; d <= degree; ++d) {
    if (degree % d) continue;
    wide_int power = 1;
    for (int e = 0; e < degree / d; ++e) {
      power *= letters;
      if (power > (static_cast<wide_int>(1) << 100)) throw std::overflow_error("free Lie dimension exceeds 64 bits");
    }
    sum += moebius(static_cast<std::uint64_t>(d)) * power;
  }
  const wide_int dim = sum / degree;
  if (dim > INT64_MAX) throw std::overflow_error("free Lie dimension exceeds 64 bits");
  return static_cast<std::int64_t>(dim);
}

}  // namespace rotlie::lie
