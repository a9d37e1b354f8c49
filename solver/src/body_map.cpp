#include "rotlie/solver/body_map.hpp"

#include <cln/real.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "rotlie/bch/families.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::solver {

namespace {

// A family whose members the exact solver takes (N, R, P).
const bch::family& solved_family(const std::string& family) {
  const auto* f = bch::find_family(family);
  if (f == nullptr || f->kind != bch::family_kind::one_free_parameter)
    throw std::invalid_argument("the family must be " +
                                bch::family_names([](const bch::family& g) { return g.kind == bch::family_kind::one_free_parameter; }) +
                                ", got '" + family + "'");
  return *f;
}

}  // namespace

std::vector<std::string> family_schemes(const std::string& family) {
  std::vector<std::string> out;
  for (const auto& m : solved_family(family).members) out.emplace_back(m.name);
  return out;
}

int family_cost(const std::string& family) { return bch::family_cost(solved_family(family)); }

int reference_cost(const std::string& name) {
  const auto t = schemes::reference_scheme(name);
  if (!t) throw std::invalid_argument("unknown reference scheme '" + name + "'");
  return schemes::cost_in_rotations(*t);
}

double reference_analytic_remainder(const lie::moments_of_inertia& body, const std::string& name,
                                    const std::string& permutation) {
  const auto table = schemes::reference_scheme(name + ":" + permutation);
  if (!table) throw std::invalid_argument("unknown reference scheme '" + name + "'");
  // The table's letters are already permuted for ABC; the layout permutes the unpermuted word itself.
  const auto base = *schemes::reference_scheme(name);
  const auto layout = bch::layout_scheme(base.word, splitting_of(base.splitting), permutation);
  std::map<std::string, double> values;
  for (std::size_t k = 0; k < layout.stages.size(); ++k) {
    const double v = std::stod(base.stages[k].value);
    const auto [at, inserted] = values.emplace(layout.stages[k].coefficient, v);
    // A name shared by two stages (the mirror half of a palindrome) must carry one value.
    if (!inserted && std::abs(at->second - v) > 1e-15 * (1 + std::abs(v)))
      throw std::logic_error(name + ": stages named " + at->first + " carry different values");
  }
  const auto unit = scaled_to_unit_I3(body);
  const std::array<cln::cl_RA, 3> w{cln::recip(unit.I[0]), cln::recip(unit.I[1]), cln::cl_RA(1)};
  const auto h = bch::compute_numeric_modified_hamiltonian(layout, w, values, 5);
  std::vector<double> q;
  for (const auto& [m, c] : h[5].terms()) q.push_back(c);
  return analytic_remainder_norm(q);
}

map_point summarize_family(const lie::moments_of_inertia& body, const std::string& family, const family_result& solved) {
  map_point p;
  p.family = family;
  for (const auto& perm : bch::permutation_names()) {
    permutation_best b;
    b.permutation = perm;
    // solutions are sorted by ‖H_R5‖ (stable): the first of this permutation is its best.
    for (const auto& s : solved.solutions)
      if (s.permutation == perm) {
        b.best = s;
        break;
      }
    p.per_permutation.push_back(std::move(b));
    p.reference_remainders.push_back(reference_analytic_remainder(body, map_reference_scheme, perm));
  }
  if (!solved.solutions.empty()) p.best = solved.solutions.front();
  for (std::size_t k = 0; k < p.reference_remainders.size(); ++k)
    if (k == 0 || p.reference_remainders[k] < p.reference_remainder) {
      p.reference_remainder = p.reference_remainders[k];
      p.reference_permutation = bch::permutation_names()[k];
    }
  if (p.best && p.best->analytic_remainder > 0)
    p.ratio = p.reference_remainder / p.best->analytic_remainder *
              std::pow(static_cast<double>(reference_cost(map_reference_scheme)) / family_cost(family), 4);
  for (const auto& r : solved.systems) {
    p.real_solutions += r.real_solutions;
    if (r.degenerate) p.singular.push_back({r.scheme, r.permutation, r.note});
  }
  return p;
}

map_point compute_map_point(const lie::moments_of_inertia& body, const std::string& family, int digits) {
  const auto solved = solve_dedicated(body, family_schemes(family), bch::permutation_names(), digits);
  return summarize_family(body, family, solved);
}

}  // namespace rotlie::solver
