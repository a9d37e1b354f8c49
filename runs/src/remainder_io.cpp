#include "rotlie/runs/remainder_io.hpp"

#include <cln/rational.h>
#include <cln/real.h>

#include <sstream>

#include "rotlie/lie/exact_number.hpp"

#include "rotlie/runs/expression_io.hpp"

namespace rotlie::runs {
namespace {

std::string split_name(const bch::remainder_result& r) { return r.layout.split == bch::splitting::abc ? "ABC" : "RS"; }

// A body in another unit moves H_Rk's coefficients by powers of its scale (H_R5 of a body in units
// of 1e-100 is ~1e500): beyond a double's range a numeric `value` would be null or 0, so the exact
// coefficient is given there as a decimal string instead (17 significant digits).
nlohmann::json value_of(const GiNaC::numeric& n) {
  static const cln::cl_RA largest = cln::expt(cln::cl_RA(10), 300), smallest = cln::recip(largest);
  if (n.is_rational()) {
    const cln::cl_RA x = cln::the<cln::cl_RA>(n.to_cl_N());
    if (!cln::zerop(x) && (cln::abs(x) > largest || cln::abs(x) < smallest)) return lie::to_decimal(x, 17);
  }
  return n.to_double();
}

std::string title(const bch::remainder_result& r) {
  std::string t = r.name.empty() ? r.layout.word : r.name + " (" + r.layout.word + ")";
  return t + ", " + split_name(r) + " splitting, permutation " + r.layout.permutation;
}

}  // namespace

nlohmann::json remainder_json(const bch::remainder_result& r) {
  nlohmann::json orders = nlohmann::json::array();
  for (int k = 2; k <= r.k.max_order; ++k) {
    nlohmann::json terms = nlohmann::json::array();
    for (const auto& [m, c] : r.k.remainder[static_cast<std::size_t>(k)].terms()) {
      nlohmann::json t = {{"G", {m[0], m[1], m[2]}}, {"coeff", format_expression(c, r.symbols, expression_style::text)}};
      if (GiNaC::is_a<GiNaC::numeric>(c)) t["value"] = value_of(GiNaC::ex_to<GiNaC::numeric>(c));
      terms.push_back(std::move(t));
    }
    orders.push_back({{"order", k}, {"terms", terms}});
  }
  nlohmann::json j = {{"word", r.layout.permuted},
                      {"split", split_name(r)},
                      {"perm", r.layout.permutation},
                      {"free", r.free},
                      {"orders", orders}};
  if (!r.name.empty()) j["scheme"] = r.name;
  return j;
}

std::string remainder_text(const bch::remainder_result& r) {
  std::ostringstream out;
  out << "Modified Hamiltonian of " << title(r) << "\n"
      << "stages: " << r.layout.permuted << "; hK = hH + sum_k h^k H_Rk, H = G1^2/(2I1) + G2^2/(2I2) + G3^2/(2I3)\n";
  for (int k = 2; k <= r.k.max_order; ++k) {
    const auto& h = r.k.remainder[static_cast<std::size_t>(k)];
    out << "\nH_R" << k << (h.is_zero() ? " = 0\n" : " =\n");
    for (const auto& [m, c] : h.terms())
      out << "  + (" << format_expression(c, r.symbols, expression_style::text) << ") * "
          << format_monomial(m, expression_style::text) << "\n";
  }
  return out.str();
}

std::string remainder_latex(const bch::remainder_result& r) {
  std::ostringstream out;
  out << "% Modified Hamiltonian of " << title(r) << "\n\\begin{align*}\n";
  bool first = true;
  for (int k = 2; k <= r.k.max_order; ++k) {
    const auto& h = r.k.remainder[static_cast<std::size_t>(k)];
    if (!first) out << " \\\\\n";
    first = false;
    out << "H_{R_{" << k << "}} &= ";
    if (h.is_zero()) out << "0";
    bool first_term = true;
    for (const auto& [m, c] : h.terms()) {
      out << (first_term ? "" : " \\\\\n &\\quad + ") << "\\left(" << format_expression(c, r.symbols, expression_style::latex)
          << "\\right) " << format_monomial(m, expression_style::latex);
      first_term = false;
    }
  }
  out << "\n\\end{align*}\n";
  return out.str();
}

}  // namespace rotlie::runs
