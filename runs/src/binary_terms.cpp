#include "rotlie/runs/binary_terms.hpp"

#include <cctype>
#include <charconv>

#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

#define ROTLIE_BINARY_TERM(NAME) binary_term_description NAME##_term();
#include "binary_term_list.hpp"
#undef ROTLIE_BINARY_TERM

const std::vector<binary_term_description>& binary_terms() {
  static const std::vector<binary_term_description> all{
#define ROTLIE_BINARY_TERM(NAME) NAME##_term(),
#include "binary_term_list.hpp"
#undef ROTLIE_BINARY_TERM
  };
  return all;
}

const binary_term_description* binary_term_named(const std::string& name) {
  for (const auto& term : binary_terms())
    if (term.name == name) return &term;
  return nullptr;
}

std::string with_named_values(const binary_term_description& term, const std::string& text) {
  std::string out;
  std::size_t start = 0;
  for (std::size_t k = 0;; ++k) {
    const auto comma = text.find(',', start);
    const std::string value = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    std::string word;
    for (const char c : value)
      if (c != ' ') word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string replaced = value;
    if (k < term.parameters.size() && !term.parameters[k].named.empty()) {
      std::string names;
      for (const auto& [name, number] : term.parameters[k].named) {
        names += (names.empty() ? "" : ", ") + name;
        if (word == name) {
          char digits[32];
          replaced.assign(digits, std::to_chars(digits, digits + sizeof digits, number).ptr);  // the shortest text that reads back
        }
      }
      if (replaced == value && !word.empty() && std::isalpha(static_cast<unsigned char>(word[0])))
        throw bad_input("--" + term.name + ": " + term.parameters[k].name + " '" + one_line(value) + "' is neither a number nor one of " + names);
    }
    out += (k ? "," : "") + replaced;
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::string term_syntax(const binary_term_description& term) {
  std::string text;
  for (const auto& p : term.parameters) text += (text.empty() ? "" : ",") + p.name + (p.unit.empty() ? "" : "[" + p.unit + "]");
  return text;
}

}  // namespace rotlie::runs
