// lie::parse_moments (--inertia) on any text. Properties: it returns a physical body (positive
// moments, the triangle inequalities of eq. 77) or throws std::invalid_argument with one
// printable line; the body printed as exact p/q text parses back to the same body.
#include <cln/rational_io.h>

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "fuzz_support.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/rigid_body.hpp"


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotlie::lie;
  using rotlie::fuzz::require;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  moments_of_inertia m;
  try {
    m = parse_moments(text);
  } catch (const std::invalid_argument& e) {
    require(rotlie::fuzz::one_line(e.what()), "the reason is one line");
    return 0;
  }
  for (const auto& I : m.I) require(cln::plusp(I), "moments are positive");
  for (int k = 0; k < 3; ++k)
    require(m.I[(k + 1) % 3] + m.I[(k + 2) % 3] >= m.I[k], "triangle inequality, eq. (77)");
  std::ostringstream again;
  again << m.I[0] << "," << m.I[1] << "," << m.I[2];
  const auto back = parse_moments(again.str());
  require(back.I == m.I, "the body printed exactly parses to the same body");
  require(symmetry_of(back) == symmetry_of(m), "same symmetry");
  return 0;
}
