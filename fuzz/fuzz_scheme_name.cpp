// schemes::reference_scheme (integrate/order --scheme NAME[:PERM]) on any text. Properties: an
// unknown name is nothing, a bad permutation a one-line std::invalid_argument; a found table meets
// the loader's contract, is its base table with letters substituted, and survives a write and a
// parse unchanged.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotlie::schemes;
  using rotlie::fuzz::require;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<scheme_table> t;
  try {
    t = reference_scheme(text);
  } catch (const std::invalid_argument& e) {
    require(rotlie::fuzz::one_line(e.what()), "the reason is one line");
    return 0;
  }
  if (!t) return 0;
  check_scheme_table(*t);
  const auto base = *reference_scheme(text.substr(0, text.find(':')));
  require(t->stages.size() == base.stages.size(), "a permutation keeps the stages");
  for (std::size_t i = 0; i < base.stages.size(); ++i) {
    const char expected = t->splitting == split::abc ? t->permutation[static_cast<std::size_t>(base.word[i] - 'A')] : base.word[i];
    require(t->word[i] == expected && t->stages[i].value == base.stages[i].value, "letters substituted, values kept");
  }
  require(parse_scheme_table(format_scheme_table(*t)) == *t, "written and parsed, the table is unchanged");
  return 0;
}
