#pragma once
// The Lyndon basis of the free Lie algebra on a few letters up to a degree, as flat arrays:
// words ordered by degree, then lexicographically; each word of length ≥ 2 knows its standard
// factorisation w = u v (v the longest proper Lyndon suffix), so P_w = [P_u, P_v].
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "rotlie/bch/word.hpp"

namespace rotlie::bch {

class lyndon_basis {
 public:
  /// letters ∈ {1, 2, 3}, 1 ≤ max_degree ≤ 31 (a word packs into 64 bits).
  lyndon_basis(int letters, int max_degree);

  int letters() const { return letters_; }
  int max_degree() const { return max_degree_; }
  std::size_t size() const { return length_.size(); }
  /// Indices [begin(d), end(d)) hold the words of degree d in lexicographic order.
  std::size_t begin(int d) const { return first_[static_cast<std::size_t>(d)]; }
  std::size_t end(int d) const { return first_[static_cast<std::size_t>(d) + 1]; }

  int length(std::size_t i) const { return length_[i]; }
  std::uint8_t letter(std::size_t i, int position) const { return letters_of_[offset_[i] + static_cast<std::size_t>(position)]; }
  const std::uint8_t* letters_of(std::size_t i) const { return letters_of_.data() + offset_[i]; }
  std::uint32_t left(std::size_t i) const { return left_[i]; }    ///< u (words of length ≥ 2)
  std::uint32_t right(std::size_t i) const { return right_[i]; }  ///< v
  /// How often each letter occurs, 8 bits per letter.
  std::uint32_t content(std::size_t i) const { return content_[i]; }

  word word_at(std::size_t i) const;
  /// The foliage with letters A, B, C ("AAB").
  std::string foliage(std::size_t i) const;
  /// Index of a Lyndon word, or size() when w is not one of this basis.
  std::size_t index_of(const word& w) const;
  std::size_t index_of(const std::uint8_t* w, int n) const;

 private:
  static std::uint64_t key(const std::uint8_t* w, int n);
  int letters_, max_degree_;
  std::vector<std::uint8_t> letters_of_;
  std::vector<std::uint32_t> offset_, left_, right_, content_;
  std::vector<std::uint8_t> length_;
  std::vector<std::size_t> first_;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
};

}  // namespace rotlie::bch
