// bch::parse_coefficient_values (--coeffs a1=1/6,b1=0.25) on any text. Properties: a list of
// distinct well-formed names with exact values, or std::invalid_argument with one line; the list
// printed back as name=p/q parses to the same list.
#include <cln/rational_io.h>

#include <cstdint>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/bch/scheme_word.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using rotlie::fuzz::require;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, cln::cl_RA>> values;
  try {
    values = rotlie::bch::parse_coefficient_values(text);
  } catch (const std::invalid_argument& e) {
    require(rotlie::fuzz::one_line(e.what()), "the reason is one line");
    return 0;
  }
  require(values.empty() == text.empty(), "only the empty text gives no values");
  std::set<std::string> names;
  std::ostringstream again;
  for (const auto& [name, value] : values) {
    require(names.insert(name).second, "names are distinct");
    require(name.size() >= 2 && name[0] >= 'a' && name[0] <= 'z' && name[1] != '0' &&
                name.find_first_not_of("0123456789", 1) == std::string::npos,
            "names are a letter and an index");
    again << (again.tellp() > 0 ? "," : "") << name << "=" << value;
  }
  require(rotlie::bch::parse_coefficient_values(again.str()) == values, "printed back, the list parses to itself");
  return 0;
}
