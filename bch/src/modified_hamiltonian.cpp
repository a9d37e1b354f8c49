#include "rotlie/bch/modified_hamiltonian.hpp"

#include <map>
#include <mutex>
#include <stdexcept>
#include <type_traits>

#include "rotlie/bch/nested_bch.hpp"
#include "rotlie/lie/poisson_bracket.hpp"
#include "rotlie/lie/theorems.hpp"

namespace rotlie::bch {
namespace {

bool is_palindrome(const std::vector<stage_element>& s) {
  for (std::size_t i = 0; i < s.size() / 2; ++i) {
    const auto& a = s[i];
    const auto& b = s[s.size() - 1 - i];
    if (!(a.coefficient - b.coefficient).expand().is_zero() || !(a.part == b.part)) return false;
  }
  return true;
}

symbolic_polynomial scaled(const stage_element& s) {
  symbolic_polynomial x;
  for (const auto& [m, c] : s.part.terms()) x.add_term(m, s.coefficient * c);
  return x;
}

}  // namespace

inverse_inertia inverse_inertia::symbolic() {
  // GiNaC symbols are equal only to themselves: one set for the whole program.
  static const GiNaC::symbol w1("w1"), w2("w2"), w3("w3");
  return {w1, w2, w3};
}
inverse_inertia inverse_inertia::abc_paper(const GiNaC::symbol& x, const GiNaC::symbol& y) {
  return {2, 2 * (1 + x), 2 * (1 + y)};
}
inverse_inertia inverse_inertia::rs_paper(const GiNaC::symbol& x, const GiNaC::symbol& y) { return {2, 2 * x, 2 * y}; }

symbolic_polynomial part_hamiltonian(char letter, splitting split, const std::string& permutation,
                                     const inverse_inertia& w) {
  auto axis = [&](std::size_t i) { return permutation[i] - 'A' + 1; };
  auto square = [](int i, const GiNaC::ex& c) {
    lie::monomial m;
    m.exponent[static_cast<std::size_t>(i - 1)] = 2;
    return symbolic_polynomial::term(m, c);
  };
  if (split == splitting::abc) {
    if (letter < 'A' || letter > 'C') throw std::invalid_argument("not an ABC part");
    const int i = letter - 'A' + 1;
    return square(i, w[i] / 2);
  }
  const int p1 = axis(0), p2 = axis(1), p3 = axis(2);
  if (letter == 'R') return square(p1, (w[p1] - w[p2]) / 2);
  if (letter == 'S') return square(p3, (w[p3] - w[p2]) / 2) + square(1, w[p2] / 2) + square(2, w[p2] / 2) + square(3, w[p2] / 2);
  throw std::invalid_argument("not an RS part");
}

lie::polynomial<cln::cl_RA> rational_part_hamiltonian(char letter, splitting split, const std::string& permutation,
                                                     const std::array<cln::cl_RA, 3>& w) {
  const inverse_inertia symbolic{GiNaC::numeric(cln::cl_N(w[0])), GiNaC::numeric(cln::cl_N(w[1])),
                                 GiNaC::numeric(cln::cl_N(w[2]))};
  lie::polynomial<cln::cl_RA> out;
  const symbolic_polynomial part = part_hamiltonian(letter, split, permutation, symbolic);
  for (const auto& [m, c] : part.terms())
    out.add_term(m, cln::the<cln::cl_RA>(GiNaC::ex_to<GiNaC::numeric>(c).to_cl_N()));
  return out;
}

namespace {

void check_order(int max_order) {
  if (max_order < 1 || max_order > max_remainder_order)
    throw std::invalid_argument("the order must be between 1 and " + std::to_string(max_remainder_order));
}

}  // namespace

// The series depend only on the order: computed once per order for the whole program.
const lie_series& cached_bch_series(int max_order, bool symmetric) {
  static std::mutex guard;
  static std::map<std::pair<int, bool>, lie_series> cache;
  const std::lock_guard<std::mutex> lock(guard);
  auto it = cache.find({max_order, symmetric});
  if (it == cache.end())
    it = cache.emplace(std::make_pair(max_order, symmetric),
                       symmetric ? symmetric_bch_series(max_order) : bch_series(max_order)).first;
  return it->second;
}

modified_hamiltonian compute_modified_hamiltonian(const std::vector<stage_element>& stages, int max_order) {
  check_order(max_order);
  if (stages.empty()) throw std::invalid_argument("a scheme needs at least one stage");
  std::vector<symbolic_polynomial> x;
  for (const auto& s : stages) x.push_back(scaled(s));
  modified_hamiltonian k;
  k.max_order = max_order;
  k.remainder = nested_bch(x, is_palindrome(stages), max_order);
  return k;
}

exact_modified_hamiltonian compute_exact_modified_hamiltonian(const scheme_layout& layout,
                                                              const std::array<cln::cl_RA, 3>& w, int max_order) {
  check_order(max_order);
  if (layout.stages.empty()) throw std::invalid_argument("a scheme needs at least one stage");
  if (layout.free_coefficients.size() > static_cast<std::size_t>(lie::coefficient_polynomial::max_unknowns))
    throw std::invalid_argument("too many free coefficients for the exact path");
  // Free coefficients are the unknowns x_0, x_1, …; each eliminated one solves its first-order condition.
  std::map<std::string, lie::coefficient_polynomial> value;
  for (std::size_t k = 0; k < layout.free_coefficients.size(); ++k)
    value.emplace(layout.free_coefficients[k], lie::coefficient_polynomial::unknown(static_cast<int>(k)));
  solve_first_order_conditions(layout, value, [](const lie::coefficient_polynomial& x, int n) {
    return x * lie::coefficient_polynomial(cln::recip(cln::cl_RA(n)));
  });
  std::vector<exact_polynomial> x;
  for (const auto& s : layout.stages) {
    exact_polynomial stage;
    const auto part = rational_part_hamiltonian(s.letter, layout.split, layout.permutation, w);
    for (const auto& [m, c] : part.terms())
      stage.add_term(m, value.at(s.coefficient) * lie::coefficient_polynomial(c));
    x.push_back(std::move(stage));
  }
  bool palindrome = true;
  for (std::size_t i = 0; i < x.size() / 2; ++i)
    palindrome = palindrome && x[i] == x[x.size() - 1 - i];
  exact_modified_hamiltonian k;
  k.max_order = max_order;
  k.unknowns = layout.free_coefficients;
  k.remainder = nested_bch(x, palindrome, max_order);
  k.coefficient_values = std::move(value);
  return k;
}

std::vector<lie::polynomial<double>> compute_numeric_modified_hamiltonian(const scheme_layout& layout,
                                                                          const std::array<cln::cl_RA, 3>& w,
                                                                          const std::map<std::string, double>& values,
                                                                          int max_order) {
  check_order(max_order);
  if (layout.stages.empty()) throw std::invalid_argument("a scheme needs at least one stage");
  std::vector<lie::polynomial<double>> x;
  for (const auto& s : layout.stages) {
    const double c = values.at(s.coefficient);
    lie::polynomial<double> stage;
    const auto part = rational_part_hamiltonian(s.letter, layout.split, layout.permutation, w);
    for (const auto& [m, p] : part.terms()) stage.add_term(m, c * cln::double_approx(p));
    x.push_back(std::move(stage));
  }
  // Palindromic in letters and coefficient names, as for the exact path (equal values suffice).
  bool palindrome = true;
  for (std::size_t i = 0; i < x.size() / 2; ++i) palindrome = palindrome && x[i] == x[x.size() - 1 - i];
  return nested_bch(x, palindrome, max_order);
}

GiNaC::ex theorem2_pairing(const symbolic_polynomial& x) {
  GiNaC::ex pairing = 0;
  for (const auto& [m, c] : x.terms()) pairing += GiNaC::numeric(cln::cl_N(lie::theorem2_weight(m))) * c;
  return pairing.expand();
}

std::vector<stage_element> stage_elements(const scheme_layout& layout, const coefficient_symbols& coefficients,
                                          const inverse_inertia& w) {
  std::vector<stage_element> out;
  for (const auto& s : layout.stages)
    out.push_back({coefficients.value.at(s.coefficient), part_hamiltonian(s.letter, layout.split, layout.permutation, w)});
  return out;
}

}  // namespace rotlie::bch
