#include "rotlie/solver/family_systems.hpp"

#include <cln/real.h>

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::solver {
namespace {

constexpr int nodes = interpolation_nodes;  // not `n`: the unity batch's other files use n for their own counts
using node_values = std::array<cln::cl_RA, nodes * nodes>;  // [a * nodes + b]: the value at w1 = a + 1, w2 = b + 1

// Divided differences on the nodes 1, 2, …, nodes (consecutive integers: the k-th difference divides by k),
// first along w2 for each w1, then along w1: the tensor Newton coefficients.
void to_newton_form(node_values& y) {
  for (int a = 0; a < nodes; ++a)
    for (int k = 1; k < nodes; ++k)
      for (int i = nodes - 1; i >= k; --i) y[a * nodes + i] = (y[a * nodes + i] - y[a * nodes + i - 1]) / k;
  for (int b = 0; b < nodes; ++b)
    for (int k = 1; k < nodes; ++k)
      for (int i = nodes - 1; i >= k; --i) y[i * nodes + b] = (y[i * nodes + b] - y[(i - 1) * nodes + b]) / k;
}

template <class T>
std::array<T, nodes> newton_basis(const T& w) {
  std::array<T, nodes> out;
  out[0] = T(1);
  for (int k = 1; k < nodes; ++k) out[k] = out[k - 1] * (w - T(k));
  return out;
}

// x-exponents → values at the nodes, for one polynomial of the system
using sampled_polynomial = std::map<std::uint32_t, node_values>;

void sample(sampled_polynomial& into, const lie::coefficient_polynomial& p, int node) {
  for (const auto& t : p.terms()) {
    auto [at, inserted] = into.try_emplace(t.key);
    if (inserted) at->second.fill(cln::cl_RA(0));
    at->second[static_cast<std::size_t>(node)] = t.c;
  }
}

body_polynomial interpolate(sampled_polynomial sampled) {
  body_polynomial out;
  for (auto& [key, values] : sampled) {
    to_newton_form(values);
    body_polynomial::term t;
    const auto e = lie::coefficient_polynomial::unpack(key);
    t.x = {e[0], e[1], e[2]};
    t.exact = values;
    for (std::size_t k = 0; k < values.size(); ++k) t.approx[k] = static_cast<long double>(cln::double_approx(values[k]));
    out.terms.push_back(std::move(t));
  }
  return out;
}

}  // namespace

body_system interpolate_system(const std::string& scheme, const std::string& perm) {
  const auto named = bch::find_named_scheme(scheme);
  if (!named) throw std::invalid_argument("unknown scheme '" + scheme + "'");
  body_system s;
  s.scheme = scheme;
  s.permutation = perm;
  s.layout = bch::layout_scheme(named->word, named->split, perm);
  s.unknowns = static_cast<int>(s.layout.free_coefficients.size());
  sampled_polynomial p1, p2;
  std::map<lie::monomial, sampled_polynomial> h5;
  for (int a = 0; a < nodes; ++a)
    for (int b = 0; b < nodes; ++b) {
      const std::array<cln::cl_RA, 3> w{cln::cl_RA(a + 1), cln::cl_RA(b + 1), cln::cl_RA(1)};
      const auto k = bch::compute_exact_modified_hamiltonian(s.layout, w, 5);
      const int node = a * nodes + b;
      sample(p1, k.remainder[3].coefficient(lie::monomial(2, 2, 0)), node);
      sample(p2, k.remainder[3].coefficient(lie::monomial(2, 0, 2)), node);
      for (const auto& [m, q] : k.remainder[5].terms()) sample(h5[m], q, node);
    }
  s.p1 = interpolate(std::move(p1));
  s.p2 = interpolate(std::move(p2));
  for (auto& [m, q] : h5) s.h5.push_back(interpolate(std::move(q)));
  std::map<std::array<int, 3>, std::size_t> row_of;
  std::vector<const body_polynomial*> all{&s.p1, &s.p2};
  for (const auto& q : s.h5) all.push_back(&q);
  for (const auto* p : all) {
    std::vector<std::size_t> rows;
    for (const auto& t : p->terms) {
      const auto [at, fresh] = row_of.try_emplace(t.x, s.monomials.size());
      if (fresh) s.monomials.push_back(t.x);
      rows.push_back(at->second);
    }
    s.rows.push_back(std::move(rows));
  }
  return s;
}

lie::coefficient_polynomial body_polynomial::at(const cln::cl_RA& w1, const cln::cl_RA& w2) const {
  const auto n1 = newton_basis(w1), n2 = newton_basis(w2);
  lie::coefficient_polynomial out;
  for (const auto& t : terms) {
    cln::cl_RA c = 0;
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b) c = c + t.exact[static_cast<std::size_t>(a * nodes + b)] * n1[a] * n2[b];
    out += lie::coefficient_polynomial::monomial({t.x[0], t.x[1], t.x[2], 0}, c);
  }
  return out;
}

const std::vector<body_system>& family_systems(const std::string& family) {
  static std::mutex guard;
  static std::map<std::string, std::unique_ptr<std::vector<body_system>>> cache;
  const std::lock_guard lock(guard);
  auto& slot = cache[family];
  if (!slot) {
    auto systems = std::make_unique<std::vector<body_system>>();
    for (const auto& scheme : family_schemes(family))
      for (const auto& perm : bch::permutation_names()) systems->push_back(interpolate_system(scheme, perm));
    slot = std::move(systems);
  }
  return *slot;
}

namespace {

long double coefficient_at(const body_polynomial::term& t, const std::array<long double, nodes>& n1,
                           const std::array<long double, nodes>& n2) {
  long double c = 0;
  for (int a = 0; a < nodes; ++a) {
    long double inner = 0;
    for (int b = 0; b < nodes; ++b) inner += t.approx[static_cast<std::size_t>(a * nodes + b)] * n2[b];
    c += inner * n1[a];
  }
  return c;
}

}  // namespace

numeric_system evaluate_system(const body_system& system, long double w1, long double w2) {
  const auto n1 = newton_basis(w1), n2 = newton_basis(w2);
  numeric_system out;
  out.unknowns = system.unknowns;
  // Each coefficient once, into the stacked form; the polynomials one by one from it.
  auto& st = out.stacked;
  st.monomials = system.monomials;
  st.count = system.rows.size();
  st.c.assign(st.monomials.size() * st.count, 0.0L);
  std::vector<const body_polynomial*> all{&system.p1, &system.p2};
  for (const auto& q : system.h5) all.push_back(&q);
  for (const auto& m : st.monomials) st.max_degree = std::max({st.max_degree, m[0], m[1], m[2]});
  for (std::size_t j = 0; j < all.size(); ++j) {
    numeric_polynomial p;
    for (std::size_t k = 0; k < all[j]->terms.size(); ++k) {
      const auto& t = all[j]->terms[k];
      const long double c = coefficient_at(t, n1, n2);
      st.c[system.rows[j][k] * st.count + j] = c;
      if (c == 0) continue;
      p.terms.push_back({t.x, c});
      p.max_degree = std::max({p.max_degree, t.x[0], t.x[1], t.x[2]});
    }
    if (j == 0) out.p1 = std::move(p);
    else if (j == 1) out.p2 = std::move(p);
    else out.h5.push_back(std::move(p));
  }
  return out;
}

}  // namespace rotlie::solver
