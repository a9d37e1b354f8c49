#include <cln/real.h>

#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/reports/remainder_io.hpp"

namespace rotlie::app {
namespace {

// "a1=1/6,b1=0.25" → (name, exact value) pairs.
std::vector<std::pair<std::string, cln::cl_RA>> parse_coefficients(const std::string& text) {
  std::vector<std::pair<std::string, cln::cl_RA>> out;
  if (text.empty()) return out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw usage_error("--coeffs: '" + item + "' is not of the form name=value");
    const std::string name = item.substr(0, eq);
    const bool well_formed = name.size() >= 2 && name[0] >= 'a' && name[0] <= 'z' &&
                             name.find_first_not_of("0123456789", 1) == std::string::npos;
    if (!well_formed) throw usage_error("--coeffs: '" + name + "' is not a coefficient name (a1, b2, …)");
    const auto value = lie::parse_exact_number(item.substr(eq + 1));
    if (!value) throw usage_error("--coeffs: " + name + " = '" + item.substr(eq + 1) + "' is not a finite number");
    for (const auto& [n, v] : out)
      if (n == name) throw usage_error("--coeffs: " + name + " is given twice");
    out.emplace_back(name, *value);
    start = comma + 1;
  }
  return out;
}

// A body in another unit moves H_Rk's coefficients by powers of its scale (H_R5 of a body in units
// of 1e-100 is ~1e500): beyond a double's range JSON's numeric `value` would be null or 0. There
// the exact coefficient is given as a decimal string instead (17 significant digits).
void values_beyond_double_as_decimals(nlohmann::json& j, const bch::remainder_result& r) {
  static const cln::cl_RA largest = cln::expt(cln::cl_RA(10), 300), smallest = cln::recip(largest);
  for (auto& order : j.at("orders")) {
    const auto& h = r.k.remainder.at(order.at("order").get<std::size_t>());
    auto term = order.at("terms").begin();
    for (const auto& [m, c] : h.terms()) {
      if (GiNaC::is_a<GiNaC::numeric>(c) && term->contains("value")) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(c);
        if (n.is_rational()) {
          const cln::cl_RA x = cln::the<cln::cl_RA>(n.to_cl_N());
          if (!cln::zerop(x) && (cln::abs(x) > largest || cln::abs(x) < smallest)) (*term)["value"] = lie::to_decimal(x, 17);
        }
      }
      ++term;
    }
  }
}

}  // namespace

int run_remainder(const remainder_options& options) {
  if (options.latex && options.json) throw usage_error("--latex and --json exclude each other");
  bch::remainder_request request;
  request.scheme = options.scheme;
  if (!options.split.empty()) {
    if (options.split != "ABC" && options.split != "RS")
      throw usage_error("--split must be ABC or RS, got '" + options.split + "'");
    request.split = options.split == "ABC" ? bch::splitting::abc : bch::splitting::rs;
  }
  request.permutation = options.perm;
  request.order = static_cast<int>(parse_integer_in_range(options.order, "--order", 1, bch::max_remainder_order));
  try {
    if (!options.inertia.empty()) request.inertia = lie::parse_moments(options.inertia);
    request.coefficients = parse_coefficients(options.coeffs);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what());
  }
  bch::remainder_result result;
  try {
    result = bch::compute_remainder(request);
  } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());
  }
  if (options.json) {
    auto j = reports::remainder_json(result);
    values_beyond_double_as_decimals(j, result);
    std::cout << j.dump(2) << "\n";
  }
  else if (options.latex)
    std::cout << reports::remainder_latex(result);
  else
    std::cout << reports::remainder_text(result);
  return 0;
}

}  // namespace rotlie::app
