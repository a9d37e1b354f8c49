#pragma once
// Rank of a set of sparse polynomials over the prime field F_p, p = 2^61 − 1.
// A nonzero minor mod p is a nonzero minor over Q, so this rank is a certified
// LOWER bound on the rank over Q of the same integer or rational vectors.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "rotlie/lie/polynomial.hpp"

namespace rotlie::lie {

class modular_echelon {
 public:
  static constexpr std::uint64_t prime = (std::uint64_t{1} << 61) - 1;

  /// Reduces v against the rows kept so far and keeps it if independent.
  /// Returns false when a coefficient's denominator vanishes mod p (the caller must then
  /// use exact arithmetic); the echelon is left unchanged in that case.
  bool add(const polynomial<cln::cl_RA>& v);
  std::size_t rank() const { return pivots_.size(); }
  /// Field operations spent so far, for benchmarks.
  std::uint64_t operations() const { return operations_; }

 private:
  using row = std::map<monomial, std::uint64_t>;
  std::map<monomial, row> pivots_;  // leading monomial → row normalised to lead coefficient 1
  std::uint64_t operations_ = 0;
};

/// x mod p for a rational x, or nothing when p divides its denominator.
std::optional<std::uint64_t> reduce_mod_prime(const cln::cl_RA& x);

}  // namespace rotlie::lie
