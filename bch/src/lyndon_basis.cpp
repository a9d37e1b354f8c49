#include "rotlie/bch/lyndon_basis.hpp"

#include <stdexcept>

namespace rotlie::bch {

std::uint64_t lyndon_basis::key(const std::uint8_t* w, int n) {
  std::uint64_t k = static_cast<std::uint64_t>(n);  // 5 bits of length, then 2 bits per letter
  for (int i = 0; i < n; ++i) k |= static_cast<std::uint64_t>(w[i]) << (5 + 2 * i);
  return k;
}

lyndon_basis::lyndon_basis(int letters, int max_degree) : letters_(letters), max_degree_(max_degree) {
  if (letters < 1 || letters > 3) throw std::invalid_argument("lyndon_basis: 1 to 3 letters");
  if (max_degree < 1 || max_degree > 29) throw std::invalid_argument("lyndon_basis: degree 1 to 29");
  // Generation in lexicographic order over all lengths (Duval's successor), bucketed by length.
  std::vector<std::vector<std::uint8_t>> by_length(static_cast<std::size_t>(max_degree) + 1);
  std::vector<int> w{-1};
  const int last = letters - 1;
  while (!w.empty()) {
    ++w.back();
    for (const int x : w) by_length[w.size()].push_back(static_cast<std::uint8_t>(x));
    const std::size_t m = w.size();
    while (w.size() < static_cast<std::size_t>(max_degree)) w.push_back(w[w.size() - m]);
    while (!w.empty() && w.back() == last) w.pop_back();
  }
  first_.push_back(0);
  first_.push_back(0);  // degree 0 is empty
  for (int d = 1; d <= max_degree; ++d) {
    const auto& flat = by_length[static_cast<std::size_t>(d)];
    for (std::size_t at = 0; at < flat.size(); at += static_cast<std::size_t>(d)) {
      const auto i = static_cast<std::uint32_t>(length_.size());
      offset_.push_back(static_cast<std::uint32_t>(letters_of_.size()));
      letters_of_.insert(letters_of_.end(), flat.begin() + static_cast<long>(at), flat.begin() + static_cast<long>(at) + d);
      length_.push_back(static_cast<std::uint8_t>(d));
      std::uint32_t c = 0;
      for (int k = 0; k < d; ++k) c += 1u << (8 * flat[at + static_cast<std::size_t>(k)]);
      content_.push_back(c);
      index_.emplace(key(letters_of(i), d), i);
      // Standard factorisation: the longest proper suffix that is itself Lyndon (shorter words
      // are already indexed).
      std::uint32_t u = 0, v = 0;
      for (int split = 1; split < d; ++split) {
        const auto it = index_.find(key(letters_of(i) + split, d - split));
        if (it == index_.end()) continue;
        v = it->second;
        u = static_cast<std::uint32_t>(index_.at(key(letters_of(i), split)));
        break;
      }
      left_.push_back(u);
      right_.push_back(v);
    }
    first_.push_back(length_.size());
  }
}

word lyndon_basis::word_at(std::size_t i) const { return word(letters_of(i), letters_of(i) + length(i)); }

std::string lyndon_basis::foliage(std::size_t i) const {
  std::string s;
  for (int k = 0; k < length(i); ++k) s.push_back(static_cast<char>('A' + letter(i, k)));
  return s;
}

std::size_t lyndon_basis::index_of(const word& w) const { return index_of(w.data(), static_cast<int>(w.size())); }

std::size_t lyndon_basis::index_of(const std::uint8_t* w, int n) const {
  if (n < 1 || n > max_degree_) return size();
  for (int i = 0; i < n; ++i)
    if (w[i] >= letters_) return size();
  const auto it = index_.find(key(w, n));
  return it == index_.end() ? size() : it->second;
}

}  // namespace rotlie::bch
