#pragma once
// Truncated formal power series in non-commuting letters with exact rational coefficients
// (the free associative algebra), graded by word length. Used to compute logarithms of
// products of exponentials before projecting them onto the Lyndon basis.
#include <cln/rational.h>

#include <map>
#include <vector>

#include "rotlie/bch/word.hpp"

namespace rotlie::bch {

class word_series {
 public:
  explicit word_series(int max_degree) : by_degree_(static_cast<std::size_t>(max_degree) + 1) {}

  int max_degree() const { return static_cast<int>(by_degree_.size()) - 1; }
  void add(const word& w, const cln::cl_RA& c);
  const std::map<word, cln::cl_RA>& degree(int d) const { return by_degree_[static_cast<std::size_t>(d)]; }

  /// The unit 1 (the empty word).
  static word_series one(int max_degree);
  /// exp(letter) = Σ_k letter^k / k!, truncated.
  static word_series exp_of_letter(std::uint8_t letter, int max_degree);

  friend word_series operator*(const word_series& a, const word_series& b);
  word_series& operator+=(const word_series& o);
  word_series& operator*=(const cln::cl_RA& s);

  /// log(x) for x with constant term 1: Σ_{k≥1} (−1)^{k+1} (x − 1)^k / k, truncated.
  friend word_series log(const word_series& x);

 private:
  std::vector<std::map<word, cln::cl_RA>> by_degree_;
};

}  // namespace rotlie::bch
