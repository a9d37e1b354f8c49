// schemes::parse_scheme_table (integrate/order --scheme FILE) on any text. Properties: a table
// meeting the loader's contract, or std::invalid_argument with one line; the same text with CRLF
// line endings or a UTF-8 byte-order mark gives the same table; written and parsed, a table is
// unchanged; a table recording its body is the same body given as its own text, as doubles, and
// scaled by 3, and not a body with I1 changed.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/schemes/same_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace {

using namespace rotlie::schemes;
using rotlie::fuzz::require;

std::optional<scheme_table> parsed(std::string_view text) {
  try {
    return parse_scheme_table(text);
  } catch (const std::invalid_argument& e) {
    require(rotlie::fuzz::one_line(e.what()), "the reason is one line");
    return std::nullopt;
  }
}

long double value_of(const std::string& text) {
  const auto slash = text.find('/');
  const long double num = std::strtold(text.substr(0, slash).c_str(), nullptr);
  return slash == std::string::npos ? num : num / std::strtold(text.substr(slash + 1).c_str(), nullptr);
}

void check_body(const scheme_table& t) {
  if (t.inertia.empty()) {
    require(same_body(t, std::array<double, 3>{1, 1, 1}) == body_match::unrecorded, "no body recorded");
    return;
  }
  std::istringstream in(t.inertia);
  std::array<std::string, 3> part;
  in >> part[0] >> part[1] >> part[2];
  require(same_body(t, {part[0], part[1], part[2]}) == body_match::same, "its own body, exactly");
  if ((part[0] + part[1] + part[2]).find('/') == std::string::npos)
    require(same_body(t, {part[0] + "/3", part[1] + "/3", part[2] + "/3"}) == body_match::same, "its own body / 3, exactly");
  std::array<long double, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) v[i] = value_of(part[i]);
  // in double when the ratios are representable: the same body, and 3× the same body
  const long double r1 = v[0] / v[2], r2 = v[1] / v[2];
  if (r1 > 1e-300L && r1 < 1e300L && r2 > 1e-300L && r2 < 1e300L) {
    const std::array<double, 3> d{static_cast<double>(r1), static_cast<double>(r2), 1.0};
    require(same_body(t, d) == body_match::same, "its own body, in double");
    require(same_body(t, std::array<double, 3>{3 * d[0], 3 * d[1], 3.0}) == body_match::same, "scaled by 3, in double");
    require(same_body(t, std::array<double, 3>{d[0] * (1 + 1e-9), d[1], 1.0}) == body_match::different, "I1 changed by 1e-9");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto t = parsed(text);

  std::string crlf;
  for (const char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const auto t_crlf = parsed(crlf);
  require(t_crlf.has_value() == t.has_value() && (!t || *t_crlf == *t), "CRLF line endings give the same table");
  if (text.rfind("\xEF\xBB\xBF", 0) != 0) {
    const auto t_bom = parsed("\xEF\xBB\xBF" + text);
    require(t_bom.has_value() == t.has_value() && (!t || *t_bom == *t), "a byte-order mark gives the same table");
  }
  if (!t) return 0;

  check_scheme_table(*t);
  require(parse_scheme_table(format_scheme_table(*t)) == *t, "written and parsed, the table is unchanged");
  check_body(*t);
  return 0;
}
