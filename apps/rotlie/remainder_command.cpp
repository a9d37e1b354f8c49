#include <cln/real.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <optional>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/reports/remainder_io.hpp"
#include "rotlie/runs/body_names.hpp"

namespace rotlie::app {
namespace {

// "a1=1/6,b1=0.25" → (name, exact value) pairs.
std::vector<std::pair<std::string, cln::cl_RA>> parse_coefficients(const std::string& text) {
  std::vector<std::pair<std::string, cln::cl_RA>> out;
  if (text.empty()) return out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw usage_error("--coeffs: '" + item + "' is not of the form name=value");
    const std::string name = item.substr(0, eq);
    const bool well_formed = name.size() >= 2 && name[0] >= 'a' && name[0] <= 'z' &&
                             name.find_first_not_of("0123456789", 1) == std::string::npos;
    if (!well_formed) throw usage_error("--coeffs: '" + name + "' is not a coefficient name (a1, b2, …)");
    const auto value = lie::parse_exact_number(item.substr(eq + 1));
    if (!value) {
      const auto why = why_not_a_number(item.substr(eq + 1));
      throw usage_error("--coeffs: " + name + " = '" + item.substr(eq + 1) + "' " +
                        (why == "is not a number" ? "is not a finite number" : why));
    }
    for (const auto& [n, v] : out)
      if (n == name) throw usage_error("--coeffs: " + name + " is given twice");
    out.emplace_back(name, *value);
    start = comma + 1;
  }
  return out;
}

// A body in another unit moves H_Rk's coefficients by powers of its scale (H_R5 of a body in units
// of 1e-100 is ~1e500): beyond a double's range JSON's numeric `value` would be null or 0. There
// the exact coefficient is given as a decimal string instead (17 significant digits).
void values_beyond_double_as_decimals(nlohmann::json& j, const bch::remainder_result& r) {
  static const cln::cl_RA largest = cln::expt(cln::cl_RA(10), 300), smallest = cln::recip(largest);
  for (auto& order : j.at("orders")) {
    const auto& h = r.k.remainder.at(order.at("order").get<std::size_t>());
    auto term = order.at("terms").begin();
    for (const auto& [m, c] : h.terms()) {
      if (GiNaC::is_a<GiNaC::numeric>(c) && term->contains("value")) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(c);
        if (n.is_rational()) {
          const cln::cl_RA x = cln::the<cln::cl_RA>(n.to_cl_N());
          if (!cln::zerop(x) && (cln::abs(x) > largest || cln::abs(x) < smallest)) (*term)["value"] = lie::to_decimal(x, 17);
        }
      }
      ++term;
    }
  }
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
    throw usage_error("--scheme: unknown scheme name '" + word +
                      "' (N1…N7, R, P1…P15, RSRSRSR, SRSRSRS, or a word such as ABCBA)");
  if (word.size() > max_word_letters)
    throw usage_error("--scheme: the word has " + std::to_string(word.size()) + " letters, at most " +
                      std::to_string(max_word_letters) + " are supported");
  const bool rs = split ? *split == bch::splitting::rs : !word.empty() && word.find_first_not_of("RS") == std::string::npos;
  const std::string parts = rs ? "RS" : "ABC";
  if (word.empty() || word.find_first_not_of(parts) != std::string::npos) return;  // the library names the bad letter
  for (const char p : parts)
    if (word.find(p) == std::string::npos)
      throw usage_error("--scheme: part " + std::string(1, p) + " never acts in the word " + word + " (every part of the " +
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
    throw usage_error("--scheme: " + word + " leaves " + std::to_string(free) + " free coefficients at --order " +
                      std::to_string(r.order) + ", at most " + std::to_string(limit) +
                      " are supported at that order (give values with --coeffs or lower --order)");
}

}  // namespace

int run_remainder(const remainder_options& options) {
  if (options.latex && options.json) throw usage_error("--latex and --json exclude each other");
  bch::remainder_request request;
  request.scheme = options.scheme;
  if (!options.split.empty()) {
    if (options.split != "ABC" && options.split != "RS")
      throw usage_error("--split must be ABC or RS, got '" + options.split + "'");
    request.split = options.split == "ABC" ? bch::splitting::abc : bch::splitting::rs;
  }
  check_word(options.scheme, request.split);
  request.permutation = options.perm;
  request.order = static_cast<int>(parse_integer_in_range(options.order, "--order", 1, bch::max_remainder_order));
  if (!options.inertia.empty()) request.inertia = runs::exact_body(options.inertia);
  request.coefficients = parse_coefficients(options.coeffs);
  check_size(request);
  bch::remainder_result result;
  try {
    result = bch::compute_remainder(request);
  } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());
  }
  if (options.json) {
    auto j = reports::remainder_json(result);
    values_beyond_double_as_decimals(j, result);
    std::cout << j.dump(2) << "\n";
  }
  else if (options.latex)
    std::cout << reports::remainder_latex(result);
  else
    std::cout << reports::remainder_text(result);
  return 0;
}

}  // namespace rotlie::app
