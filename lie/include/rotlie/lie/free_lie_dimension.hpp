#pragma once
// Dimension of the degree-k part of the free Lie algebra on n letters (Witt's necklace formula):
//   dim = (1/k) Σ_{d | k} μ(d) n^(k/d).
#include <cstdint>

namespace rotlie::lie {

/// Möbius function μ(n), n ≥ 1.
int moebius(std::uint64_t n);

/// Witt's formula. Throws std::overflow_error when the value leaves 64-bit range.
std::int64_t free_lie_dimension(int letters, int degree);

}  // namespace rotlie::lie
