#include "rotlie/bch/stage_hamiltonian.hpp"

#include <stdexcept>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/nested_bch.hpp"

namespace rotlie::bch {

stage_hamiltonian compute_stage_hamiltonian(const scheme_layout& layout, const std::array<cln::cl_RA, 3>& w, int max_order) {
  if (max_order < 1 || max_order > max_remainder_order)
    throw std::invalid_argument("the order must be between 1 and " + std::to_string(max_remainder_order));
  if (layout.stages.empty()) throw std::invalid_argument("a scheme needs at least one stage");
  if (layout.free_coefficients.size() > static_cast<std::size_t>(lie::multivariate_polynomial::max_unknowns))
    throw std::invalid_argument("more than 16 free coefficients");
  using poly = lie::multivariate_polynomial;
  std::map<std::string, poly> value;
  for (std::size_t k = 0; k < layout.free_coefficients.size(); ++k)
    value.emplace(layout.free_coefficients[k], poly::unknown(static_cast<int>(k)));
  solve_first_order_conditions(layout, value, [](const poly& x, int n) { return x * poly(cln::recip(cln::cl_RA(n))); });
  // H_Rk is homogeneous of degree k in w: the expansion runs with integer moments λw, λ the lcm of
  // their denominators (small numbers throughout), and order k is divided by λ^k at the end.
  const cln::cl_I lambda = cln::lcm(cln::lcm(cln::denominator(w[0]), cln::denominator(w[1])), cln::denominator(w[2]));
  const std::array<cln::cl_RA, 3> scaled{w[0] * lambda, w[1] * lambda, w[2] * lambda};
  std::vector<stage_polynomial> x;
  for (const auto& s : layout.stages) {
    stage_polynomial stage;
    const auto part = rational_part_hamiltonian(s.letter, layout.split, layout.permutation, scaled);
    for (const auto& [m, c] : part.terms())
      stage.add_term(m, value.at(s.coefficient) * poly(c));
    x.push_back(std::move(stage));
  }
  // The layout names mirrored stages alike, so a palindrome in names is one in values.
  bool palindrome = true;
  for (std::size_t i = 0; i < x.size() / 2; ++i) palindrome = palindrome && x[i] == x[x.size() - 1 - i];
  stage_hamiltonian k;
  k.max_order = max_order;
  k.unknowns = layout.free_coefficients;
  k.remainder = nested_bch(x, palindrome, max_order);
  for (int order = 1; order <= max_order; ++order) {
    const cln::cl_RA scale = cln::recip(cln::expt(cln::cl_RA(lambda), order));
    stage_polynomial h;
    for (const auto& [m, c] : k.remainder[static_cast<std::size_t>(order)].terms()) h.add_term(m, c * lie::multivariate_polynomial(scale));
    k.remainder[static_cast<std::size_t>(order)] = std::move(h);
  }
  k.coefficient_values = std::move(value);
  return k;
}

}  // namespace rotlie::bch
