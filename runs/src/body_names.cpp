#include "rotlie/runs/body_names.hpp"

#include <cln/integer.h>
#include <cln/rational_io.h>
#include <cln/real.h>

#include "rotlie/lie/exact_number.hpp"
#include "exact_range.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

lie::moments_of_inertia required_body(const std::string& text) {
  if (text.empty()) throw bad_input("--inertia is required (I1,I2,I3, water or sphere)");
  try {
    return lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--inertia: ") + e.what());
  }
}

lie::moments_of_inertia exact_body(const std::string& text) {
  if (text.empty()) throw bad_input("--inertia must not be empty (I1,I2,I3, water or sphere)");
  // A value written as a number but beyond the exact parser's limits is out of range, not "not a number".
  std::size_t start = 0;
  for (int i = 1; i <= 3 && start <= text.size(); ++i) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, comma - start);
    if (!lie::parse_exact_number(part) && why_not_a_number(part).rfind("is out of range", 0) == 0)
      throw bad_input("--inertia: I" + std::to_string(i) + " = '" + part + "' is out of range");
    start = comma + 1;
  }
  try {
    return lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--inertia: ") + e.what());
  }
}

lie::moments_of_inertia numeric_body(const std::string& text) {
  const auto m = exact_body(text);
  for (std::size_t i = 0; i < 3; ++i)
    if (!magnitude_in_range(m.I[i]))
      throw bad_input("--inertia: I" + std::to_string(i + 1) + " = " + shown(m.I[i]) + " is outside the range " +
                      range_text() + " of the numeric subcommands");
  return m;
}

models::vec3<double> to_double(const lie::moments_of_inertia& body) {
  return {cln::double_approx(body.I[0]), cln::double_approx(body.I[1]), cln::double_approx(body.I[2])};
}

}  // namespace rotlie::runs
