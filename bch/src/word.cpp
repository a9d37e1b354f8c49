#include "rotlie/bch/word.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotlie::bch {

bool is_lyndon(const word& w) {
  if (w.empty()) return false;
  for (std::size_t i = 1; i < w.size(); ++i) {
    // compare w with its rotation starting at i
    word rotation(w.begin() + static_cast<long>(i), w.end());
    rotation.insert(rotation.end(), w.begin(), w.begin() + static_cast<long>(i));
    if (!(w < rotation)) return false;
  }
  return true;
}

std::vector<word> lyndon_words(int letters, int max_length) {
  std::vector<word> out;
  if (letters < 1 || max_length < 1) return out;
  const int last = letters - 1;
  std::vector<int> w{-1};
  while (!w.empty()) {
    ++w.back();
    out.emplace_back(w.begin(), w.end());
    const std::size_t m = w.size();
    while (w.size() < static_cast<std::size_t>(max_length)) w.push_back(w[w.size() - m]);
    while (!w.empty() && w.back() == last) w.pop_back();
  }
  std::stable_sort(out.begin(), out.end(), [](const word& a, const word& b) { return a.size() < b.size(); });
  return out;
}

std::pair<word, word> standard_factorization(const word& w) {
  if (w.size() < 2) throw std::invalid_argument("standard_factorization needs a word of length ≥ 2");
  for (std::size_t i = 1; i < w.size(); ++i) {
    word v(w.begin() + static_cast<long>(i), w.end());
    if (is_lyndon(v)) return {word(w.begin(), w.begin() + static_cast<long>(i)), v};
  }
  throw std::logic_error("a word of length ≥ 2 always has a Lyndon suffix (its last letter)");
}

std::string bracket_text(const word& w) {
  if (w.size() == 1) return std::string(1, static_cast<char>('A' + w[0]));
  const auto [u, v] = standard_factorization(w);
  return "[" + bracket_text(u) + "," + bracket_text(v) + "]";
}

}  // namespace rotlie::bch
