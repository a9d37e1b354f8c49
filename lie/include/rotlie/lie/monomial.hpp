#pragma once
// A monomial G1^e1 G2^e2 G3^e3 in the body angular momentum, and the total order used
// everywhere for printing and pivoting (degree first, then exponents), never GiNaC's.
#include <array>
#include <compare>
#include <cstdint>
#include <string>

namespace rotlie::lie {

struct monomial {
  std::array<std::uint32_t, 3> exponent{0, 0, 0};

  constexpr monomial() = default;
  constexpr monomial(std::uint32_t e1, std::uint32_t e2, std::uint32_t e3) : exponent{e1, e2, e3} {}

  constexpr std::uint32_t degree() const { return exponent[0] + exponent[1] + exponent[2]; }
  constexpr std::uint32_t operator[](int i) const { return exponent[static_cast<std::size_t>(i)]; }
  constexpr bool operator==(const monomial&) const = default;

  /// Degree ascending, then G1's exponent descending, then G2's: G1² < G2² < G3² < G1²G2² < …
  constexpr std::strong_ordering operator<=>(const monomial& o) const {
    if (auto c = degree() <=> o.degree(); c != 0) return c;
    if (auto c = o.exponent[0] <=> exponent[0]; c != 0) return c;
    if (auto c = o.exponent[1] <=> exponent[1]; c != 0) return c;
    return o.exponent[2] <=> exponent[2];
  }
};

/// "G1^2*G2*G3" style text (ASCII, parseable by humans and by GiNaC-free tools); "1" for the constant.
std::string to_string(const monomial& m);

/// "G1^2G2^4" (every exponent written, no separator, empty for the constant): how the solver names the
/// conditions of a table, one per remainder coefficient.
std::string compact_text(const monomial& m);

}  // namespace rotlie::lie
