#include "rotlie/runs/remainder_run.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {
namespace {

bool is_coefficient_name(const std::string& name) {
  return name.size() >= 2 && name[0] >= 'a' && name[0] <= 'z' && name.find_first_not_of("0123456789", 1) == std::string::npos;
}

// The values, exact, each checked once.
std::vector<std::pair<std::string, cln::cl_RA>> coefficient_values(const std::vector<coefficient_text>& given) {
  std::vector<std::pair<std::string, cln::cl_RA>> out;
  for (const auto& [name, text] : given) {
    if (!is_coefficient_name(name)) throw bad_input("--coeffs: '" + name + "' is not a coefficient name (a1, b2, …)");
    const auto value = lie::parse_exact_number(text);
    if (!value) {
      const auto why = why_not_a_number(text);
      throw bad_input("--coeffs: " + name + " = '" + text + "' " + (why == "is not a number" ? "is not a finite number" : why));
    }
    for (const auto& [n, v] : out)
      if (n == name) throw bad_input("--coeffs: " + name + " is given twice");
    out.emplace_back(name, *value);
  }
  return out;
}

// A raw word's size, checked before any algebra: the number of BCH terms grows with the word
// length and the order, and the longest words of the paper have 11 letters (P1…P15, eq. 69).
constexpr std::size_t max_word_letters = 40;

bool looks_like_a_name(const std::string& s) {
  const auto digit = s.find_first_of("0123456789");
  return digit != std::string::npos && digit > 0 && s.find_first_not_of("0123456789", digit) == std::string::npos;
}

// The checks of a raw word that need no algebra: its length, and that every part acts (as the
// table loader demands: a part that never acts cannot meet its first-order condition).
void check_word(const std::string& word, const std::optional<bch::splitting>& split) {
  if (bch::find_named_scheme(word)) return;
  if (looks_like_a_name(word))
    throw bad_input("--scheme: unknown scheme name '" + word + "' (N1…N7, R, P1…P15, RSRSRSR, SRSRSRS, or a word such as ABCBA)");
  if (word.size() > max_word_letters)
    throw bad_input("--scheme: the word has " + std::to_string(word.size()) + " letters, at most " +
                    std::to_string(max_word_letters) + " are supported");
  const bool rs = split ? *split == bch::splitting::rs : !word.empty() && word.find_first_not_of("RS") == std::string::npos;
  const std::string parts = rs ? "RS" : "ABC";
  if (word.empty() || word.find_first_not_of(parts) != std::string::npos) return;  // the library names the bad letter
  for (const char p : parts)
    if (word.find(p) == std::string::npos)
      throw bad_input("--scheme: part " + std::string(1, p) + " never acts in the word " + word + " (every part of the " +
                      parts + " splitting must appear)");
}

// The work grows about tenfold per free coefficient left symbolic, and faster with the order
// (RS words faster still): the most free coefficients a raw word may leave at each order K
// (index), measured to stay within about 20 s with symbolic moments. The paper's named schemes
// are always accepted (P1 at order 9 takes about 40 s, RSRSRSR at order 9 a few minutes).
constexpr std::array<std::size_t, bch::max_remainder_order + 1> max_free_abc = {0, 40, 40, 40, 18, 10, 6, 4, 3, 3};
constexpr std::array<std::size_t, bch::max_remainder_order + 1> max_free_rs = {0, 40, 40, 40, 18, 8, 4, 2, 2, 1};

void check_size(const bch::remainder_request& r) {
  if (bch::find_named_scheme(r.scheme)) return;
  const std::string& word = r.scheme;
  const auto split =
      r.split.value_or(word.find_first_not_of("RS") == std::string::npos ? bch::splitting::rs : bch::splitting::abc);
  bch::scheme_layout layout;
  try {
    layout = bch::layout_scheme(word, split, r.permutation);
  } catch (const std::invalid_argument&) {
    return;  // a malformed word: compute_remainder names the problem
  }
  std::size_t free = 0;
  for (const auto& name : layout.free_coefficients)
    free += std::none_of(r.coefficients.begin(), r.coefficients.end(), [&](const auto& c) { return c.first == name; });
  const auto limit = (split == bch::splitting::rs ? max_free_rs : max_free_abc).at(static_cast<std::size_t>(r.order));
  if (free > limit)
    throw bad_input("--scheme: " + word + " leaves " + std::to_string(free) + " free coefficients at --order " +
                    std::to_string(r.order) + ", at most " + std::to_string(limit) +
                    " are supported at that order (give values with --coeffs or lower --order)");
}

}  // namespace

std::vector<coefficient_text> coefficient_list(std::string_view text) {
  try {
    const auto pairs = bch::split_assignments(text);
    return {pairs.begin(), pairs.end()};
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--coeffs: ") + e.what());
  }
}

bch::remainder_result remainder_run(const remainder_inputs& in) {
  bch::remainder_request request;
  request.scheme = in.scheme;
  if (!in.split.empty()) {
    if (in.split != "ABC" && in.split != "RS") throw bad_input("--split must be ABC or RS, got '" + in.split + "'");
    request.split = in.split == "ABC" ? bch::splitting::abc : bch::splitting::rs;
  }
  check_word(in.scheme, request.split);
  request.permutation = in.perm;
  request.order = static_cast<int>(integer_in_range(in.order, "--order", 1, bch::max_remainder_order));
  if (!in.inertia.empty()) request.inertia = exact_body(in.inertia);
  request.coefficients = coefficient_values(in.coefficients);
  check_size(request);
  try {
    return bch::compute_remainder(request);
  } catch (const std::invalid_argument& e) {
    throw bad_input(e.what());
  }
}

}  // namespace rotlie::runs
