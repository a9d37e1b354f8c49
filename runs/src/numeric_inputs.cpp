#include "rotlie/runs/numeric_inputs.hpp"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cmath>

#include "exact_range.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

namespace {
constexpr double whole_steps_slack = 1e-9;  // T/h of decimals typed from a float (0.333333333333)
}  // namespace

double positive_number(const std::string& text, const std::string& what) {
  const auto x = lie::parse_exact_number(text);
  if (!x) {
    const auto why = why_not_a_number(text);
    if (why == "is not a number") throw bad_input(what + " must be a number such as 0.01 or 1/64, got '" + text + "'");
    throw bad_input(what + " '" + text + "' " + why);
  }
  if (!cln::plusp(*x)) throw bad_input(what + " must be positive, got '" + text + "'");
  if (!magnitude_in_range(*x)) throw bad_input(what + " '" + text + "' is outside the range " + range_text());
  return cln::double_approx(*x);
}

std::vector<double> positive_numbers(const std::string& text, const std::string& what) {
  std::vector<double> out;
  for (std::size_t start = 0;;) {
    const auto comma = text.find(',', start);
    out.push_back(positive_number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), what));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

double real_number(const std::string& text, const std::string& what) {
  const auto x = lie::parse_exact_number(text);
  if (!x) {
    const auto why = why_not_a_number(text);
    if (why == "is not a number") throw bad_input(what + " must be a number such as -0.5 or 1/64, got '" + one_line(text) + "'");
    throw bad_input(what + " '" + one_line(text) + "' " + why);
  }
  if (!cln::zerop(*x) && !magnitude_in_range(*x)) throw bad_input(what + " '" + one_line(text) + "' is outside the range " + range_text() + " (or 0)");
  return cln::double_approx(*x);
}

std::vector<double> real_numbers(const std::string& text, const std::string& what) {
  std::vector<double> out;
  for (std::size_t start = 0;;) {
    const auto comma = text.find(',', start);
    out.push_back(real_number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), what));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

models::vec3<double> initial_momentum(const std::string& text) {
  models::vec3<double> g{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos)) throw bad_input("--G0 takes three components g1,g2,g3, got '" + text + "'");
    const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    const auto x = lie::parse_exact_number(part);
    if (!x) throw bad_input("--G0: g" + std::to_string(i + 1) + " = '" + part + "' " + why_not_a_number(part));
    if (!magnitude_in_range(*x) && cln::abs(*x) > 1)
      throw bad_input("--G0: g" + std::to_string(i + 1) + " = '" + part + "' is outside the range " + range_text());
    g[i] = cln::double_approx(*x);  // a component below the range may round to 0: only |G0| matters
    start = comma + 1;
  }
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) throw bad_input("--G0 must not be zero, got '" + text + "'");
  const double length = std::hypot(g[0], g[1], g[2]), range = std::pow(10.0, max_decimal_exponent);
  if (length * range < 1) throw bad_input("--G0: |G0| = " + shown(length) + " is outside the range " + range_text());
  // Squares of smaller components underflow in double: the computation could not see them.
  for (std::size_t i = 0; i < 3; ++i)
    if (g[i] != 0 && std::abs(g[i]) * range < length)
      throw bad_input("--G0: g" + std::to_string(i + 1) + " = " + shown(g[i]) + " is below 1e-" +
                      std::to_string(max_decimal_exponent) + " |G0|; give 0 or a larger value");
  return g;
}

void check_numeric_scales(const std::string& inertia, const std::string& g0, const std::string& total) {
  const auto I = to_double(numeric_body(inertia));
  const auto g = initial_momentum(g0);
  const double T = positive_number(total, "--T");
  const double smallest = std::min({I[0], I[1], I[2]});
  const double rate = std::hypot(g[0], g[1], g[2]) / smallest;  // ≤ 1e300: finite
  const double limit = std::pow(10.0, max_decimal_exponent);
  if (rate > limit || rate < 1 / limit)
    throw bad_input("the angular rate |G0|/I_min = " + shown(rate) + " of --G0 and --inertia is outside the range " +
                    range_text());
  if (rate * T > limit)
    throw bad_input("--T: the body turns by |G0| T / I_min = " + shown(rate * T) + " radians, outside the range " +
                    range_text());
}

long whole_steps(const std::string& h_text, const std::string& T_text, double h, double T) {
  const auto exact_h = lie::parse_exact_number(h_text), exact_T = lie::parse_exact_number(T_text);
  double steps = std::round(T / h);
  bool whole = false;
  if (exact_h && exact_T) {
    const cln::cl_RA q = *exact_T / *exact_h;
    whole = cln::denominator(q) == 1;
  }
  whole = whole || (steps >= 1 && std::abs(T / h - steps) <= whole_steps_slack * steps);
  if (steps > max_steps || T / h > max_steps) throw bad_input("--T/--h is over the limit of 2e9 steps");
  if (!whole || steps < 1) {
    const double below = std::floor(T / h), above = std::ceil(T / h);
    std::string choices = below >= 1 ? "--T " + schemes::message_number(below * h) + " or " : std::string();
    choices += "--T " + schemes::message_number(above * h);
    throw bad_input("--T " + one_line(T_text) + " is not a whole number of steps --h " + one_line(h_text) + " (T/h = " + schemes::message_number(T / h) +
                    "): take " + choices + ", or a step that divides T");
  }
  return static_cast<long>(steps);
}

}  // namespace rotlie::runs
