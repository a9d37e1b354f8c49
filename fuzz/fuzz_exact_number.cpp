// lie::parse_exact_number on any text. Properties: a refusal always has a reason; a value lies in
// the stated range; the exact rational text (p/q) reads back exactly; to_decimal with d digits
// reads back within half a unit of its last digit, and printing that value again gives the same text.
#include <cln/integer.h>
#include <cln/rational_io.h>

#include <cstdint>
#include <sstream>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/lie/exact_number.hpp"


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotlie::lie;
  using rotlie::fuzz::require;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto parsed = parse_exact_number_checked(text);
  require(parsed.value.has_value() == parsed.problem.empty(), "a value xor a reason");
  require(parse_exact_number(text).has_value() == parsed.value.has_value(), "both entry points agree");
  if (!parsed.value) {
    require(rotlie::fuzz::one_line(parsed.problem), "the reason is one line");
    return 0;
  }
  const cln::cl_RA x = *parsed.value;
  const cln::cl_RA bound = cln::expt_pos(cln::cl_I(10), static_cast<unsigned int>(max_decimal_exponent));
  require(cln::zerop(x) || (cln::abs(x) <= bound && cln::abs(x) * bound >= 1), "value within 1e-400 … 1e400");

  std::ostringstream exact;
  exact << x;
  const auto back = parse_exact_number(exact.str());
  require(back && *back == x, "p/q text reads back exactly");

  for (const int digits : {1, 2, 17, 40}) {
    const std::string d = to_decimal(x, digits);
    const auto y = parse_exact_number(d);
    require(y.has_value(), "to_decimal output parses");
    // |y − x| ≤ ½·10^(e−digits+1) ≤ ½·|x|·10^(1−digits)
    const cln::cl_I scale = digits == 1 ? cln::cl_I(1) : cln::expt_pos(cln::cl_I(10), static_cast<unsigned int>(digits - 1));
    require(2 * cln::abs(*y - x) * scale <= cln::abs(x),
            "to_decimal within half a unit of its last digit");
    require(to_decimal(*y, digits) == d, "to_decimal is idempotent");
  }
  return 0;
}
