#pragma once
// Splitting-scheme words and their stage coefficients, named as in the paper (DESIGN.md):
// letters get the names a, b, c in order of first appearance in the unpermuted word; each stage
// of the first half (middle included) of a palindrome takes the next index of its name and the
// second half mirrors it; the first-order conditions eliminate the highest index of each name.
#include <cln/rational.h>
#include <ginac/ginac.h>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotlie::bch {

enum class splitting { abc, rs };

struct named_scheme {
  std::string_view name;
  std::string_view word;
  splitting split;
};

/// The paper's named words: N1–N7 (eq. 52), R (eq. 65), P1–P15 (eq. 69), RSRSRSR and SRSRSRS (eq. 41).
const std::vector<named_scheme>& named_schemes();
std::optional<named_scheme> find_named_scheme(std::string_view name);

/// The six permutations of section 2.1 in the paper's order: ABC, BCA, CAB, ACB, CBA, BAC.
const std::vector<std::string>& permutation_names();
bool is_permutation_name(std::string_view p);

struct stage {
  char letter = 'A';           ///< part letter after the permutation (A, B, C; or R, S)
  std::string coefficient;     ///< e.g. "a1"
};

struct scheme_layout {
  std::string word;                  ///< as given (unpermuted)
  std::string permuted;              ///< letters after the permutation (ABC splitting only; RS keeps R, S)
  splitting split = splitting::abc;
  std::string permutation = "ABC";
  bool symmetric = false;            ///< a palindrome in letters and coefficient names
  std::vector<stage> stages;
  std::vector<std::string> free_coefficients;  ///< in order of first appearance, e.g. a1, b1
  std::vector<std::string> eliminated;         ///< fixed by the first-order conditions
};

/// Longest word accepted: the symbolic remainder grows steeply with the length (a 25-stage palindrome
/// takes 4 s at order 5, 33 stages 36 s; max_remainder_stages in remainder_request.hpp limits each
/// order further). The paper's longest word has 11 stages, Suzuki's SS5 composition of ABCBA 21.
inline constexpr std::size_t max_word_length = 25;

/// Validates and names a word; throws std::invalid_argument with a one-line reason
/// (empty word, longer than max_word_length, a letter outside the splitting, a part of the
/// splitting that never acts, unknown permutation).
scheme_layout layout_scheme(std::string_view word, splitting split, std::string_view permutation = "ABC");

/// "a1=1/6,b1=0.25" → (name, exact value) pairs: names are a letter and an index (a1, b2, …),
/// values exact numbers (lie::parse_exact_number), each name at most once; empty text → none.
/// Throws std::invalid_argument with a one-line reason.
std::vector<std::pair<std::string, cln::cl_RA>> parse_coefficient_values(std::string_view text);

/// "a1=1/6,b1=1/2" split into (name, value text) pairs, nothing checked but the form; throws
/// std::invalid_argument for an item without '='. Empty text: no pairs.
std::vector<std::pair<std::string, std::string>> split_assignments(std::string_view text);

/// Symbols for the free coefficients and expressions for the eliminated ones (first-order
/// conditions: Σ of each name's coefficients over the stages = 1).
struct coefficient_symbols {
  std::map<std::string, GiNaC::symbol> free;       ///< name → symbol
  std::map<std::string, GiNaC::ex> value;          ///< every name → its expression in the free symbols
};
coefficient_symbols make_coefficients(const scheme_layout& layout);

/// The same first-order solve in any coefficient ring R: `value` holds the free coefficients on entry
/// and every coefficient on exit; `divide(x, n)` is x / n in R.
template <class R, class Divide>
void solve_first_order_conditions(const scheme_layout& layout, std::map<std::string, R>& value, Divide divide) {
  for (const auto& last : layout.eliminated) {
    // Σ over stages carrying this name's letter = 1, solved for `last`.
    R others = R(0);
    int multiplicity = 0;
    for (const auto& s : layout.stages) {
      if (s.coefficient[0] != last[0]) continue;
      if (s.coefficient == last)
        ++multiplicity;
      else
        others = others + value.at(s.coefficient);
    }
    value.emplace(last, divide(R(1) - others, multiplicity));
  }
}

}  // namespace rotlie::bch
