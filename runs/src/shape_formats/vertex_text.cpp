#include "vertex_text.hpp"

#include <charconv>
#include <cmath>

#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs::shape_formats {

models::vec3<double> vertex_of(std::istream& words, const std::function<void(const std::string&)>& refuse) {
  models::vec3<double> v;
  for (auto& x : v) {
    std::string word;
    if (!(words >> word)) refuse("a vertex needs three finite coordinates");
    const std::size_t sign = word[0] == '+' ? 1 : 0;
    const auto [end, error] = std::from_chars(word.data() + sign, word.data() + word.size(), x);
    if (error == std::errc::result_out_of_range)
      refuse("vertex coordinate " + one_line(word) + " is out of range (a double holds sizes from 2.2e-308 to 1.8e308)");
    if (error != std::errc() || end != word.data() + word.size()) refuse("vertex coordinate '" + one_line(word) + "' is not a number");
    if (!std::isfinite(x)) refuse("vertex coordinate " + one_line(word) + " is not finite");
    if (std::abs(x) > largest_coordinate)
      refuse("vertex coordinate " + one_line(word) + " is out of range (at most " + schemes::message_number(largest_coordinate) + " km in size)");
  }
  return v;
}

}  // namespace rotlie::runs::shape_formats
