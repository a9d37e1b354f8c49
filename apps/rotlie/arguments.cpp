#include "arguments.hpp"

#include <charconv>

namespace rotlie::app {

long parse_integer_in_range(std::string_view text, std::string_view option, long lo, long hi) {
  const std::string name(option);
  const std::string shown(text);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || (ec != std::errc() && ec != std::errc::result_out_of_range) || end != digits.data() + digits.size())
    throw usage_error(name + ": '" + shown + "' is not an integer");
  const bool too_small = ec == std::errc::result_out_of_range ? digits.front() == '-' : value < lo;
  const bool too_large = ec == std::errc::result_out_of_range ? digits.front() != '-' : value > hi;
  if (too_small) throw usage_error(name + " must be at least " + std::to_string(lo) + ", got " + shown);
  if (too_large) throw usage_error(name + " must be at most " + std::to_string(hi) + ", got " + shown);
  return value;
}

}  // namespace rotlie::app
