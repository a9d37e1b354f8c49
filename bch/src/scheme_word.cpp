#include "rotlie/bch/scheme_word.hpp"

#include <algorithm>
#include <stdexcept>

#include "rotlie/bch/families.hpp"
#include "rotlie/lie/exact_number.hpp"

namespace rotlie::bch {

const std::vector<named_scheme>& named_schemes() {
  static const std::vector<named_scheme> schemes = [] {
    std::vector<named_scheme> all;
    for (const auto& f : families()) all.insert(all.end(), f.members.begin(), f.members.end());
    all.push_back({"RSRSRSR", "RSRSRSR", splitting::rs});  // eq. (41)
    all.push_back({"SRSRSRS", "SRSRSRS", splitting::rs});
    return all;
  }();
  return schemes;
}

std::optional<named_scheme> find_named_scheme(std::string_view name) {
  for (const auto& s : named_schemes())
    if (s.name == name) return s;
  return std::nullopt;
}

const std::vector<std::string>& permutation_names() {
  static const std::vector<std::string> names = {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"};
  return names;
}

bool is_permutation_name(std::string_view p) {
  const auto& n = permutation_names();
  return std::find(n.begin(), n.end(), p) != n.end();
}

scheme_layout layout_scheme(std::string_view stages, splitting split, std::string_view permutation) {
  if (stages.empty()) throw std::invalid_argument("the scheme word is empty");
  if (stages.size() > max_word_length)
    throw std::invalid_argument("the scheme word has " + std::to_string(stages.size()) + " stages; at most " +
                                std::to_string(max_word_length) + " are supported");
  const std::string allowed = split == splitting::abc ? "ABC" : "RS";
  const std::string split_name = split == splitting::abc ? "ABC" : "RS";
  for (const char c : stages)
    if (allowed.find(c) == std::string::npos)
      throw std::invalid_argument("letter '" + lie::printable_text(std::string_view(&c, 1)) + "' is not a part of the " + split_name +
                                  " splitting (allowed: " + allowed + ")");
  // H is the sum of every part: a part that never acts leaves it out of the flow (H_R1 ≠ H).
  for (const char c : allowed)
    if (stages.find(c) == std::string_view::npos)
      throw std::invalid_argument("part " + std::string(1, c) + " never acts in " + lie::printable_text(stages) + ": every part of the " +
                                  split_name + " splitting must appear");
  if (!is_permutation_name(permutation))
    throw std::invalid_argument("unknown permutation '" + lie::printable_text(permutation) +
                                "' (expected ABC, BCA, CAB, ACB, CBA or BAC)");

  scheme_layout layout;
  layout.word = std::string(stages);
  layout.split = split;
  layout.permutation = std::string(permutation);
  layout.permuted = layout.word;
  if (split == splitting::abc)
    for (char& c : layout.permuted) c = permutation[static_cast<std::size_t>(c - 'A')];

  std::map<char, char> name_of;  // word letter → a, b, c in order of first appearance
  for (const char c : stages)
    if (!name_of.count(c)) name_of.emplace(c, static_cast<char>('a' + name_of.size()));

  const std::size_t n = stages.size();
  layout.symmetric = std::equal(stages.begin(), stages.begin() + static_cast<long>(n / 2), stages.rbegin());
  std::map<char, int> next_index;
  layout.stages.resize(n);
  const std::size_t named = layout.symmetric ? (n + 1) / 2 : n;
  for (std::size_t i = 0; i < named; ++i) {
    const char name = name_of[stages[i]];
    layout.stages[i] = {layout.permuted[i], std::string(1, name) + std::to_string(++next_index[name])};
  }
  for (std::size_t i = named; i < n; ++i) layout.stages[i] = {layout.permuted[i], layout.stages[n - 1 - i].coefficient};

  // The highest index of each name is eliminated by its first-order condition.
  for (const auto& [letter, name] : name_of) {
    const std::string last = std::string(1, name) + std::to_string(next_index[name]);
    layout.eliminated.push_back(last);
  }
  for (std::size_t i = 0; i < named; ++i) {
    const auto& c = layout.stages[i].coefficient;
    const bool dropped = std::find(layout.eliminated.begin(), layout.eliminated.end(), c) != layout.eliminated.end();
    if (!dropped && std::find(layout.free_coefficients.begin(), layout.free_coefficients.end(), c) ==
                        layout.free_coefficients.end())
      layout.free_coefficients.push_back(c);
  }
  std::sort(layout.eliminated.begin(), layout.eliminated.end());
  return layout;
}

coefficient_symbols make_coefficients(const scheme_layout& layout) {
  coefficient_symbols out;
  for (const auto& name : layout.free_coefficients) {
    out.free.emplace(name, GiNaC::symbol(name));
    out.value.emplace(name, out.free.at(name));
  }
  solve_first_order_conditions(layout, out.value, [](const GiNaC::ex& x, int n) { return (x / n).expand(); });
  return out;
}

std::vector<std::pair<std::string, std::string>> split_assignments(std::string_view text) {
  std::vector<std::pair<std::string, std::string>> out;
  if (text.empty()) return out;
  for (std::size_t start = 0; start <= text.size();) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string item(text.substr(start, comma - start));
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("'" + lie::printable_text(item) + "' is not of the form name=value");
    out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
    start = comma + 1;
  }
  return out;
}

std::vector<std::pair<std::string, cln::cl_RA>> parse_coefficient_values(std::string_view text) {
  std::vector<std::pair<std::string, cln::cl_RA>> out;
  for (const auto& [name, text_value] : split_assignments(text)) {
    const bool well_formed = name.size() >= 2 && name.size() <= 4 && name[0] >= 'a' && name[0] <= 'z' && name[1] != '0' &&
                             name.find_first_not_of("0123456789", 1) == std::string::npos;
    if (!well_formed) throw std::invalid_argument("'" + lie::printable_text(name) + "' is not a coefficient name (a1, b2, …)");
    const auto value = lie::parse_exact_number_checked(text_value);
    if (!value.value) throw std::invalid_argument(name + " = '" + lie::printable_text(text_value) + "' " + value.problem);
    for (const auto& [n, v] : out)
      if (n == name) throw std::invalid_argument(name + " is given twice");
    out.emplace_back(name, *value.value);
  }
  return out;
}

}  // namespace rotlie::bch
