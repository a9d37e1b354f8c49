#include "rotlie/runs/binary_terms.hpp"

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

std::string term_syntax(const binary_term_description& term) {
  std::string text;
  for (const auto& p : term.parameters) text += (text.empty() ? "" : ",") + p.name + (p.unit.empty() ? "" : "[" + p.unit + "]");
  return text;
}

}  // namespace rotlie::runs
