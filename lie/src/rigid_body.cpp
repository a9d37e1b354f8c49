#include "rotlie/lie/rigid_body.hpp"

#include <cln/rational_io.h>

#include <sstream>
#include <stdexcept>

#include "rotlie/lie/exact_number.hpp"

namespace rotlie::lie {

moments_of_inertia parse_moments(std::string_view text) {
  if (text == "water") return {{cln::cl_RA(10220) / 29376, cln::cl_RA(19187) / 29376, cln::cl_RA(1)}};
  if (text == "sphere") return {{cln::cl_RA(1), cln::cl_RA(1), cln::cl_RA(1)}};
  moments_of_inertia m;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string_view::npos))
      throw std::invalid_argument("inertia must be three values I1,I2,I3 (or water, sphere), got '" + printable_text(text) + "'");
    const auto piece = text.substr(start, i < 2 ? comma - start : std::string_view::npos);
    const auto value = parse_exact_number_checked(piece);
    if (!value.value)
      throw std::invalid_argument("I" + std::to_string(i + 1) + " = '" + printable_text(piece) + "' " + value.problem);
    m.I[static_cast<std::size_t>(i)] = *value.value;
    start = comma + 1;
  }
  validate_moments(m);
  return m;
}

void validate_moments(const moments_of_inertia& m) {
  for (int i = 0; i < 3; ++i)
    if (!cln::plusp(m.I[static_cast<std::size_t>(i)]))
      throw std::invalid_argument("I" + std::to_string(i + 1) + " = " + to_decimal(m.I[static_cast<std::size_t>(i)], 6) +
                                  " is not positive: moments of inertia must be > 0");
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>((k + 1) % 3), j = static_cast<std::size_t>((k + 2) % 3);
    const auto kk = static_cast<std::size_t>(k);
    if (m.I[i] + m.I[j] < m.I[kk])
      throw std::invalid_argument("not a physical body: I" + std::to_string(i + 1) + " + I" + std::to_string(j + 1) +
                                  " < I" + std::to_string(k + 1) + " (" + to_decimal(m.I[i], 6) + " + " +
                                  to_decimal(m.I[j], 6) + " < " + to_decimal(m.I[kk], 6) +
                                  "), violating the triangle inequality of eq. (77)");
  }
}

std::string inertia_text(const moments_of_inertia& m) {
  std::ostringstream text;
  text << m.I[0] << " " << m.I[1] << " " << m.I[2];  // p/q or an integer, exactly
  return text.str();
}

std::string symmetry_of(const moments_of_inertia& m) {
  if (m.I[0] == m.I[1] && m.I[1] == m.I[2]) return "I1 = I2 = I3";
  if (m.I[0] == m.I[1]) return "I1 = I2";
  if (m.I[1] == m.I[2]) return "I2 = I3";
  if (m.I[0] == m.I[2]) return "I1 = I3";
  return "";
}

}  // namespace rotlie::lie
