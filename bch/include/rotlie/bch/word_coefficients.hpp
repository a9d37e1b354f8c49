#pragma once
// Coefficients of single words in log(e^{X_g1} e^{X_g2} … e^{X_gm}) (the free associative algebra,
// letters X_0 = A, X_1 = B, X_2 = C), as exact integers over the degree's denominator
// D_n = n! · lcm(1, …, n), by dynamic programming over the word (no series is expanded).
#include <array>
#include <vector>

#include "rotlie/bch/int128.hpp"
#include "rotlie/bch/lyndon_basis.hpp"

namespace rotlie::bch {

/// D_n = n! · lcm(1 … n).
int128 word_denominator(int n);

/// z_w · D_n for words w of length n, for the product of exponentials of the letters `factors`
/// (e.g. {0, 1} for e^A e^B). The table of the previous word is kept: words in lexicographic order
/// share prefixes, and only the rows past the common prefix are recomputed.
/// Exact: every partial sum is a non-negative term of a sum bounded by Fubini(n) · m^n · lcm(1…n)
/// (m = factors.size()), checked below 2^126 by check_word_coefficient_bound.
class word_coefficients {
 public:
  explicit word_coefficients(std::vector<std::uint8_t> factors);
  int128 operator()(const std::uint8_t* w, int n);

 private:
  static constexpr int max_n = 31;
  std::vector<std::uint8_t> factors_;
  std::array<std::uint8_t, max_n> previous_{};
  int previous_n_ = -1;
  std::array<int, max_n + 1> run_start_{};
  std::array<std::array<int128, max_n + 1>, max_n + 1> e_{};  // e_[p][k]
  std::array<int128, max_n + 1> log_weight_{};                // of e_[n][k] in z_w · D_n
  void set_log_weights(int n);
};

/// Throws std::overflow_error when the bound above exceeds 2^126 for this degree and product.
void check_word_coefficient_bound(int n, std::size_t factors);

}  // namespace rotlie::bch
