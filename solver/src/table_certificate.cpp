#include "rotlie/solver/table_certificate.hpp"

#include <cln/integer.h>
#include <cln/real.h>

#include <array>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/exact_number.hpp"

namespace rotlie::solver {
namespace {

// |value| / Σ|terms| of one condition (0 when every term vanishes: then so does the value).
cln::cl_RA relative(const cln::cl_RA& value, const cln::cl_RA& size) {
  return cln::zerop(size) ? cln::cl_RA(0) : cln::abs(value) / size;
}

// A coefficient polynomial of H_Rk at x: (value, Σ over its terms of |term|), exactly.
std::pair<cln::cl_RA, cln::cl_RA> value_and_size(const lie::coefficient_polynomial& c, const std::vector<cln::cl_RA>& x) {
  cln::cl_RA value = 0, size = 0;
  for (const auto& t : c.terms()) {
    const auto e = lie::coefficient_polynomial::unpack(t.key);
    cln::cl_RA term = t.c;
    for (std::size_t k = 0; k < x.size(); ++k) term = term * cln::expt(x[k], e[k]);
    value = value + term;
    size = size + cln::abs(term);
  }
  return {value, size};
}

// One condition checked: keeps the largest relative residual, and the first failure per order.
struct tally {
  explicit tally(const cln::cl_RA& t) : tolerance(t) {}
  cln::cl_RA tolerance, worst = 0;
  std::array<std::string, 5> failure{};  // index = order whose condition fails (1: first order)
  void check(int order, const cln::cl_RA& r, const std::string& what) {
    worst = cln::max(worst, r);
    if (r > tolerance && failure[static_cast<std::size_t>(order)].empty())
      failure[static_cast<std::size_t>(order)] = what + " is " + lie::to_decimal(r, 3) + " of its terms (tolerance " +
                                                  lie::to_decimal(tolerance, 1) + ")";
  }
};

}  // namespace

cln::cl_RA certificate_tolerance(int digits) { return cln::recip(cln::expt(cln::cl_RA(10), digits - 5)); }

cln::cl_RA written_value(const cln::cl_RA& x, int digits) {
  const auto v = lie::parse_exact_number(lie::to_decimal(x, digits));
  if (!v) throw std::invalid_argument("a coefficient of " + lie::to_decimal(x, 3) + " cannot be written as a table's decimal");
  return *v;
}

order_certificate certify_order_four(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                                     const std::map<std::string, cln::cl_RA>& values, int digits) {
  const auto at = [&](const std::string& name) {
    const auto it = values.find(name);
    if (it == values.end()) throw std::invalid_argument("no value for the coefficient " + name);
    return it->second;
  };
  tally t{certificate_tolerance(digits)};
  // First order: Σ of each name's stage values = 1, relative to Σ|values| + 1.
  std::map<char, std::pair<cln::cl_RA, cln::cl_RA>> sums;  // name letter → (Σ c, Σ |c|)
  for (const auto& s : layout.stages) {
    auto& [sum, size] = sums[s.coefficient[0]];
    sum = sum + at(s.coefficient);
    size = size + cln::abs(at(s.coefficient));
  }
  for (const auto& [name, sum_size] : sums)
    t.check(1, relative(sum_size.first - 1, sum_size.second + 1), std::string("the first-order condition on ") + name);
  // H_R2 … H_R4 as polynomials in the free coefficients (the others solve the first-order conditions,
  // checked above), for the body scaled to I3 = 1: the same zero set and the same ratios at any scale.
  const std::array<cln::cl_RA, 3> w{body.I[2] / body.I[0], body.I[2] / body.I[1], cln::cl_RA(1)};
  const int top = layout.symmetric ? 3 : 4;  // a palindrome's even remainders vanish identically
  const auto k = bch::compute_exact_modified_hamiltonian(layout, w, top);
  std::vector<cln::cl_RA> x;
  for (const auto& name : layout.free_coefficients) x.push_back(at(name));
  for (int order = 2; order <= top; ++order)
    for (const auto& [m, c] : k.remainder[static_cast<std::size_t>(order)].terms()) {
      const auto [value, size] = value_and_size(c, x);
      t.check(order, relative(value, size), "the coefficient of " + lie::compact_text(m) + " in H_R" + std::to_string(order));
    }
  order_certificate out;
  out.residual = t.worst;
  out.order = 4;
  for (int order = 1; order <= 4; ++order) {
    // A failing condition of H_R(k) leaves order k − 1 (first order: order 0).
    const std::string& f = t.failure[static_cast<std::size_t>(order)];
    if (!f.empty()) {
      out.order = order == 1 ? 0 : order - 1;
      out.failure = f;
      break;
    }
  }
  return out;
}

namespace {

std::vector<std::string> fields(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string f; in >> f;) out.push_back(f);
  return out;
}

cln::cl_RA exact_field(const std::string& text, const std::string& what) {
  const auto v = lie::parse_exact_number(text);
  if (!v) throw std::invalid_argument("scheme table: " + what + " '" + text + "' is not a number");
  return *v;
}

}  // namespace

order_certificate certify_scheme_table_text(std::string_view text) {
  std::map<std::string, std::vector<std::string>> header;
  std::vector<std::vector<std::string>> stages;
  std::istringstream in{std::string(text)};
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    auto f = fields(line);
    if (f.empty()) continue;
    const std::string key = f.front();
    f.erase(f.begin());
    if (key == "stage")
      stages.push_back(std::move(f));
    else
      header[key] = std::move(f);
  }
  const auto one = [&](const std::string& key) {
    const auto it = header.find(key);
    if (it == header.end() || it->second.empty()) throw std::invalid_argument("scheme table: no '" + key + "' line");
    return it->second.front();
  };
  const std::string scheme = one("scheme");
  const std::string split_text = one("split");
  if (split_text != "ABC" && split_text != "RS") throw std::invalid_argument("scheme table: split must be ABC or RS");
  const auto named = bch::find_named_scheme(scheme);
  const auto layout = bch::layout_scheme(named ? named->word : std::string_view(scheme),
                                         split_text == "ABC" ? bch::splitting::abc : bch::splitting::rs,
                                         one("permutation"));
  const auto& inertia = header["inertia"];
  if (inertia.size() != 3) throw std::invalid_argument("scheme table: the inertia line needs three moments");
  lie::moments_of_inertia body;
  for (std::size_t i = 0; i < 3; ++i) body.I[i] = exact_field(inertia[i], "moment");
  lie::validate_moments(body);
  const cln::cl_RA digits = exact_field(one("digits"), "digits");
  if (cln::denominator(digits) != 1 || digits < 6 || digits > 1000) throw std::invalid_argument("scheme table: digits out of range");
  const int stated_digits = static_cast<int>(cln::cl_I_to_long(cln::numerator(digits)));
  if (stages.size() != layout.stages.size())
    throw std::invalid_argument("scheme table: " + std::to_string(stages.size()) + " stages, the word has " +
                                std::to_string(layout.stages.size()));
  std::map<std::string, cln::cl_RA> values;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const auto& s = stages[i];
    const auto& want = layout.stages[i];
    if (s.size() < 3 || s[0] != std::string(1, want.letter) || s[1] != want.coefficient)
      throw std::invalid_argument("scheme table: stage " + std::to_string(i + 1) + " is not " + want.letter + " " +
                                  want.coefficient);
    const cln::cl_RA v = exact_field(s[2], "coefficient");
    if (const auto it = values.find(s[1]); it != values.end() && it->second != v)
      throw std::invalid_argument("scheme table: " + s[1] + " has two values");
    values[s[1]] = v;
  }
  return certify_order_four(layout, body, values, stated_digits);
}

}  // namespace rotlie::solver
