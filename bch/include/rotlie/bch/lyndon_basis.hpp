#pragma once
// The Lyndon basis of the free Lie algebra on a few letters up to a degree, as flat arrays:
// words ordered by degree, then lexicographically; each word of length ≥ 2 knows its standard
// factorisation w = u v (v the longest proper Lyndon suffix), so P_w = [P_u, P_v].
//
// A word is kept packed in one integer, its code: a leading 1 bit, then its letters, the first one
// highest, in bits_per_letter() bits each. Codes increase with the basis order (a longer word has a
// higher leading bit; words of one length compare as numbers as they do lexicographically), so the
// index of a word is a binary search: no table besides the codes and the factorisations.
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "rotlie/bch/word.hpp"

namespace rotlie::bch {

class lyndon_basis {
 public:
  /// letters ∈ {1, 2, 3}, 1 ≤ max_degree ≤ 29 (a code fits in 64 bits).
  lyndon_basis(int letters, int max_degree);

  int letters() const { return letters_; }
  int max_degree() const { return max_degree_; }
  std::size_t size() const { return left_.size(); }
  /// Indices [begin(d), end(d)) hold the words of degree d in lexicographic order.
  std::size_t begin(int d) const { return first_[static_cast<std::size_t>(d)]; }
  std::size_t end(int d) const { return first_[static_cast<std::size_t>(d) + 1]; }

  /// 1 with two letters (or one), 2 with three.
  int bits_per_letter() const { return bits_; }
  std::uint64_t code(std::size_t i) const { return code64_.empty() ? code32_[i] : code64_[i]; }
  int length(std::size_t i) const { return length_of_code(code(i)); }
  std::uint8_t letter(std::size_t i, int position) const {
    const std::uint64_t c = code(i);
    return static_cast<std::uint8_t>((c >> (bits_ * (length_of_code(c) - 1 - position))) & letter_mask());
  }
  /// The letters of word i into out[0 : length(i)].
  void copy_letters(std::size_t i, std::uint8_t* out) const;
  std::uint32_t left(std::size_t i) const { return left_[i]; }    ///< u (words of length ≥ 2)
  std::uint32_t right(std::size_t i) const { return right_[i]; }  ///< v
  /// How often each letter occurs, 8 bits per letter.
  std::uint32_t content(std::size_t i) const;

  word word_at(std::size_t i) const;
  /// The foliage with letters A, B, C ("AAB").
  std::string foliage(std::size_t i) const;
  /// Index of a Lyndon word, or size() when w is not one of this basis.
  std::size_t index_of(const word& w) const;
  std::size_t index_of(const std::uint8_t* w, int n) const;
  /// Index of the word with this code, or size().
  std::size_t index_of_code(std::uint64_t code) const;

  /// The code of w[0 : n] (letters below letters(), n ≤ max_degree()).
  std::uint64_t code_of(const std::uint8_t* w, int n) const;
  int length_of_code(std::uint64_t code) const { return (static_cast<int>(std::bit_width(code)) - 1) >> (bits_ - 1); }
  /// The code of the last n letters of a word of length ≥ n.
  std::uint64_t suffix_code(std::uint64_t code, int n) const {
    const std::uint64_t top = std::uint64_t{1} << (bits_ * n);
    return (code & (top - 1)) | top;
  }

 private:
  std::uint64_t letter_mask() const { return (std::uint64_t{1} << bits_) - 1; }
  template <class Code>
  void build(std::vector<Code>& codes);
  template <class Code>
  std::size_t find(const std::vector<Code>& codes, std::uint64_t code) const;

  int letters_, max_degree_, bits_;
  std::vector<std::uint32_t> code32_;  // when every code fits in 32 bits,
  std::vector<std::uint64_t> code64_;  // else these
  std::vector<std::uint32_t> left_, right_;
  std::vector<std::size_t> first_;
};

}  // namespace rotlie::bch
