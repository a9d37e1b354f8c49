#include "scheme_lookup.hpp"

#include <cln/real.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "arguments.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/reports/protocol_curves.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::app {

lie::moments_of_inertia parse_inertia_option(const std::string& text) {
  if (text.empty()) throw usage_error("--inertia is required (I1,I2,I3, water or sphere)");
  try {
    return lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what());
  }
}

models::vec3<double> to_double(const lie::moments_of_inertia& body) {
  return {cln::double_approx(body.I[0]), cln::double_approx(body.I[1]), cln::double_approx(body.I[2])};
}

double parse_positive(const std::string& text, const std::string& what) {
  const auto x = lie::parse_exact_number(text);
  if (!x) throw usage_error(what + " must be a number such as 0.01 or 1/64, got '" + text + "'");
  if (!cln::plusp(*x)) throw usage_error(what + " must be positive, got '" + text + "'");
  const double v = cln::double_approx(*x);
  if (!std::isfinite(v) || v == 0) throw usage_error(what + " is out of range: '" + text + "'");
  return v;
}

models::vec3<double> parse_momentum(const std::string& text) {
  models::vec3<double> g{};
  std::istringstream in(text);
  std::string part;
  std::size_t i = 0;
  while (std::getline(in, part, ',')) {
    if (i == 3) throw usage_error("--G0 takes three components g1,g2,g3");
    const auto x = lie::parse_exact_number(part);
    if (!x) throw usage_error("--G0: '" + part + "' is not a number");
    g[i++] = cln::double_approx(*x);
  }
  if (i != 3) throw usage_error("--G0 takes three components g1,g2,g3");
  for (const double c : g)
    if (!std::isfinite(c)) throw usage_error("--G0 components must be finite");
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) throw usage_error("--G0 must not be zero");
  return g;
}

schemes::scheme_table lookup_scheme(const std::string& name, const lie::moments_of_inertia& body) {
  if (name.empty()) throw usage_error("--scheme is required");
  try {
    if (auto t = schemes::reference_scheme(name)) return *t;
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--scheme: ") + e.what());
  }
  if (std::filesystem::is_regular_file(name)) {
    std::ifstream in(name);
    std::ostringstream text;
    text << in.rdbuf();
    try {
      return schemes::parse_scheme_table(text.str());
    } catch (const std::invalid_argument& e) {
      throw usage_error(name + ": " + e.what());
    }
  }
  // SCHEME:PERM:LABEL
  const auto first = name.find(':'), second = name.find(':', first == std::string::npos ? first : first + 1);
  if (first != std::string::npos && second != std::string::npos) {
    const std::string scheme = name.substr(0, first), perm = name.substr(first + 1, second - first - 1);
    const std::string label_text = name.substr(second + 1);
    const auto named = bch::find_named_scheme(scheme);
    if (!named) throw usage_error("--scheme: unknown dedicated scheme '" + scheme + "' in '" + name + "'");
    if (!bch::is_permutation_name(perm)) throw usage_error("--scheme: unknown permutation '" + perm + "' in '" + name + "'");
    const long label = parse_integer_in_range(label_text, "--scheme label", 1, 1000);
    const auto r = solver::solve_dedicated(body, {scheme}, {perm}, 40);
    for (const auto& s : r.solutions)
      if (s.label == label) return reports::table_of(s, body);
    std::string why = r.systems.empty() || r.systems[0].note.empty() ? "" : " (" + r.systems[0].note + ")";
    throw usage_error("--scheme: " + scheme + " " + perm + " has " + std::to_string(r.solutions.size()) +
                      " real solutions for this body, no label " + label_text + why);
  }
  throw usage_error("--scheme: unknown scheme '" + name +
                    "' (a reference name such as RS4-S5-McLachlan:CBA, SCHEME:PERM:LABEL such as N2:BAC:2, or a scheme-table file)");
}

}  // namespace rotlie::app
