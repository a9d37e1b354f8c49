// bch scheme words and names (rotlie remainder --scheme WORD --split … --perm …): the first byte
// picks the splitting (ABC, RS, or as the remainder request infers it) and the permutation (one of
// the six, or a bad one); the rest is the paper's name or a raw word. Properties of an accepted
// word: at most max_word_length stages, every part of the splitting acts, the layout is a
// palindrome exactly when the word is, the permutation substitutes letters, every coefficient name
// is free or eliminated, and the first-order conditions give Σ = 1 per part (exactly, in GiNaC).
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/bch/scheme_word.hpp"

namespace {

using namespace rotlie::bch;
using rotlie::fuzz::require;

void check_layout(const scheme_layout& l, std::string_view word, splitting split, const std::string& perm) {
  const std::string letters = split == splitting::abc ? "ABC" : "RS";
  require(!word.empty() && word.size() <= max_word_length, "word length within the limit");
  require(l.stages.size() == word.size() && l.permuted.size() == word.size(), "one stage per letter");
  for (const char c : letters) require(word.find(c) != std::string_view::npos, "every part acts");
  const std::string reversed(word.rbegin(), word.rend());
  require(l.symmetric == (reversed == word), "symmetric exactly for palindromes");
  std::set<std::string> names;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char expected = split == splitting::abc ? perm[static_cast<std::size_t>(word[i] - 'A')] : word[i];
    require(l.permuted[i] == expected && l.stages[i].letter == expected, "the permutation substitutes letters");
    if (l.symmetric) require(l.stages[i].coefficient == l.stages[word.size() - 1 - i].coefficient, "mirrored names");
    names.insert(l.stages[i].coefficient);
  }
  std::set<std::string> named(l.free_coefficients.begin(), l.free_coefficients.end());
  for (const auto& e : l.eliminated) require(named.insert(e).second, "free and eliminated are disjoint");
  require(named == names, "every name is free or eliminated");
  require(l.eliminated.size() == letters.size(), "one first-order condition per part");

  const auto c = make_coefficients(l);
  for (const auto& e : l.eliminated) {
    GiNaC::ex sum = 0;
    for (const auto& s : l.stages)
      if (s.coefficient[0] == e[0]) sum += c.value.at(s.coefficient);
    require((sum - 1).expand().is_zero(), "Σ of each part's coefficients = 1");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int mode = data[0] % 3;
  const int p = (data[0] / 3) % 7;
  const std::string perm = p < 6 ? permutation_names()[static_cast<std::size_t>(p)] : "ABD";
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);

  // As the remainder request resolves it: a paper name fixes word and splitting; otherwise the
  // splitting given, or RS for a word of R and S only.
  std::string word(text);
  splitting split = mode == 1 ? splitting::rs : splitting::abc;
  if (const auto named = find_named_scheme(text)) {
    word = std::string(named->word);
    split = named->split;
    require(named->name == text, "a name finds itself");
  } else if (mode == 2 && !word.empty() && word.find_first_not_of("RS") == std::string::npos) {
    split = splitting::rs;
  }
  try {
    const auto layout = layout_scheme(word, split, perm);
    require(p < 6, "an unknown permutation is refused");
    check_layout(layout, word, split, perm);
  } catch (const std::invalid_argument& e) {
    require(rotlie::fuzz::one_line(e.what()), "the reason is one line");
  }
  return 0;
}
