#include "rotlie/reports/remainder_io.hpp"

#include <sstream>

#include "rotlie/reports/expression_io.hpp"

namespace rotlie::reports {
namespace {

std::string split_name(const bch::remainder_result& r) { return r.layout.split == bch::splitting::abc ? "ABC" : "RS"; }

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
      if (GiNaC::is_a<GiNaC::numeric>(c)) t["value"] = GiNaC::ex_to<GiNaC::numeric>(c).to_double();
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

}  // namespace rotlie::reports
