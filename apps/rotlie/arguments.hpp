#pragma once
// Validation of command-line values, with one-line messages that name the option.
#include <stdexcept>
#include <string>
#include <string_view>

namespace rotlie::app {

/// A bad command-line value: reported as one line on stderr, exit status 2.
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses a decimal integer in [lo, hi]; throws usage_error naming `option` otherwise.
long parse_integer_in_range(std::string_view text, std::string_view option, long lo, long hi);

}  // namespace rotlie::app
