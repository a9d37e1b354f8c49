#include "rotlie/bch/lyndon_basis.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace rotlie::bch {
namespace {

// Length of the lexicographically smallest proper suffix of the Lyndon word with these d letters
// (its standard right factor). Suffixes are compared left-aligned on d letters: a tie means the
// shorter one is a prefix of the longer (padded with letter 0), hence the smaller.
int right_factor_length(std::uint64_t letters, int d, int bits) {
  int best = 1;
  std::uint64_t best_aligned = (letters & ((std::uint64_t{1} << bits) - 1)) << (bits * (d - 1));
  for (int n = 2; n < d; ++n) {
    const std::uint64_t aligned = (letters & ((std::uint64_t{1} << (bits * n)) - 1)) << (bits * (d - n));
    if (aligned < best_aligned) best = n, best_aligned = aligned;
  }
  return best;
}

// Calls emit(length, code) for every Lyndon word of length ≤ n over `letters` letters, in
// lexicographic order (Duval's successor: repeat the word periodically up to length n, drop the
// trailing largest letters, increment the last one).
template <class Emit>
void each_lyndon_word(int letters, int n, int bits, Emit&& emit) {
  std::array<std::uint8_t, 64> w{};
  std::array<std::uint64_t, 65> prefix{};  // prefix[k]: w[0 : k] packed
  const int last = letters - 1;
  for (int m = 1;;) {
    prefix[static_cast<std::size_t>(m)] = (prefix[static_cast<std::size_t>(m - 1)] << bits) | w[static_cast<std::size_t>(m - 1)];
    emit(m, prefix[static_cast<std::size_t>(m)] | (std::uint64_t{1} << (bits * m)));
    for (int k = m; k < n; ++k) {
      w[static_cast<std::size_t>(k)] = w[static_cast<std::size_t>(k - m)];
      prefix[static_cast<std::size_t>(k + 1)] = (prefix[static_cast<std::size_t>(k)] << bits) | w[static_cast<std::size_t>(k)];
    }
    int k = n;
    while (k > 0 && w[static_cast<std::size_t>(k - 1)] == last) --k;
    if (k == 0) return;
    ++w[static_cast<std::size_t>(k - 1)];
    m = k;
  }
}

}  // namespace

lyndon_basis::lyndon_basis(int letters, int max_degree)
    : letters_(letters), max_degree_(max_degree), bits_(letters == 3 ? 2 : 1) {
  if (letters < 1 || letters > 3) throw std::invalid_argument("lyndon_basis: 1 to 3 letters");
  if (max_degree < 1 || max_degree > 29) throw std::invalid_argument("lyndon_basis: degree 1 to 29");
  if (bits_ * max_degree + 1 <= 32)
    build(code32_);
  else
    build(code64_);
}

template <class Code>
void lyndon_basis::build(std::vector<Code>& codes) {
  std::vector<std::size_t> count(static_cast<std::size_t>(max_degree_) + 1, 0);
  each_lyndon_word(letters_, max_degree_, bits_, [&](int m, std::uint64_t) { ++count[static_cast<std::size_t>(m)]; });
  first_.assign(2, 0);  // degree 0 is empty
  for (int d = 1; d <= max_degree_; ++d) first_.push_back(first_.back() + count[static_cast<std::size_t>(d)]);
  codes.resize(first_.back());
  std::vector<std::size_t> at(first_.begin(), first_.end() - 1);
  each_lyndon_word(letters_, max_degree_, bits_,
                   [&](int m, std::uint64_t c) { codes[at[static_cast<std::size_t>(m)]++] = static_cast<Code>(c); });
  // Standard factorisations, from the shorter words already placed.
  left_.assign(codes.size(), 0);
  right_.assign(codes.size(), 0);
  for (int d = 2; d <= max_degree_; ++d)
    for (std::size_t i = begin(d); i < end(d); ++i) {
      const int n = right_factor_length(codes[i], d, bits_);
      left_[i] = static_cast<std::uint32_t>(find(codes, codes[i] >> (bits_ * n)));
      right_[i] = static_cast<std::uint32_t>(find(codes, suffix_code(codes[i], n)));
    }
}

template <class Code>
std::size_t lyndon_basis::find(const std::vector<Code>& codes, std::uint64_t code) const {
  const int d = length_of_code(code);
  const auto first = codes.begin() + static_cast<long>(begin(d)), last = codes.begin() + static_cast<long>(end(d));
  const auto it = std::lower_bound(first, last, static_cast<Code>(code));
  return it != last && *it == code ? static_cast<std::size_t>(it - codes.begin()) : size();
}

void lyndon_basis::copy_letters(std::size_t i, std::uint8_t* out) const {
  const std::uint64_t c = code(i);
  const int n = length_of_code(c);
  for (int k = 0; k < n; ++k) out[k] = static_cast<std::uint8_t>((c >> (bits_ * (n - 1 - k))) & letter_mask());
}

std::uint32_t lyndon_basis::content(std::size_t i) const {
  const std::uint64_t c = code(i);
  const auto n = static_cast<std::uint32_t>(length_of_code(c));
  if (bits_ == 1) {
    const auto ones = static_cast<std::uint32_t>(std::popcount(c)) - 1;  // less the leading bit
    return (n - ones) | (letters_ == 2 ? ones << 8 : 0u);
  }
  // letter 1 = 01, letter 2 = 10; the leading bit sits at an even place
  const auto ones = static_cast<std::uint32_t>(std::popcount(c & 0x5555555555555555ull)) - 1;
  const auto twos = static_cast<std::uint32_t>(std::popcount(c & 0xaaaaaaaaaaaaaaaaull));
  return (n - ones - twos) | ones << 8 | twos << 16;
}

word lyndon_basis::word_at(std::size_t i) const {
  word w(static_cast<std::size_t>(length(i)));
  copy_letters(i, w.data());
  return w;
}

std::string lyndon_basis::foliage(std::size_t i) const {
  std::string s(static_cast<std::size_t>(length(i)), 'A');
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = static_cast<char>('A' + letter(i, static_cast<int>(k)));
  return s;
}

std::uint64_t lyndon_basis::code_of(const std::uint8_t* w, int n) const {
  std::uint64_t c = 1;
  for (int i = 0; i < n; ++i) c = (c << bits_) | w[i];
  return c;
}

std::size_t lyndon_basis::index_of(const word& w) const { return index_of(w.data(), static_cast<int>(w.size())); }

std::size_t lyndon_basis::index_of(const std::uint8_t* w, int n) const {
  if (n < 1 || n > max_degree_) return size();
  for (int i = 0; i < n; ++i)
    if (w[i] >= letters_) return size();
  return index_of_code(code_of(w, n));
}

std::size_t lyndon_basis::index_of_code(std::uint64_t code) const {
  if (code < 2 || (std::bit_width(code) - 1) % bits_ != 0) return size();
  const int d = length_of_code(code);
  if (d > max_degree_) return size();
  return code64_.empty() ? find(code32_, code) : find(code64_, code);
}

}  // namespace rotlie::bch
