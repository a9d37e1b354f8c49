#include "rotlie/runs/measured_best.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {
namespace {

long steps_for_cost(int cost) {
  return std::max(1L, std::lround(static_cast<double>(measured_best_steps_per_cost) / cost));
}

// Mean R^9 distance to precomputed exact attitudes; no allocation in the step loop.
struct distance_to_exact {
  const std::vector<std::array<double, 9>>* exact;
  double sum = 0;
  void operator()(long k, const double&, const models::body_state<double>& s) {
    const auto& e = (*exact)[static_cast<std::size_t>(k - 1)];
    double d = 0;
    for (std::size_t i = 0; i < 9; ++i) d += (s.Q.a[i] - e[i]) * (s.Q.a[i] - e[i]);
    sum += std::sqrt(d);
  }
};

}  // namespace

fixed_reduced_step_protocol::fixed_reduced_step_protocol(const lie::moments_of_inertia& body)
    : inertia_(lie::inertia_text(body)) {}

const std::vector<std::array<double, 9>>& fixed_reduced_step_protocol::exact_attitudes(long n) const {
  if (auto it = exact_.find(n); it != exact_.end()) return it->second;
  models::body_state<long double> initial;
  initial.G = {1, 1, 1};  // LV section 4.1
  // long double, redone in float128 above 1e-17: far below the errors at h/C = 1/1980 (≥ 1e-13 here)
  const models::exact_free_body<long double> exact(models::moments_from_text<long double>(inertia_), initial, 1e-17);
  std::vector<std::array<double, 9>> q(static_cast<std::size_t>(n));
  for (long k = 1; k <= n; ++k) {
    const auto s = exact.at(static_cast<long double>(k) / static_cast<long double>(n));
    for (std::size_t i = 0; i < 9; ++i) q[static_cast<std::size_t>(k - 1)][i] = static_cast<double>(s.Q.a[i]);
  }
  return exact_.emplace(n, std::move(q)).first->second;
}

double fixed_reduced_step_protocol::error(const schemes::scheme_table& table) const {
  const auto method = models::free_body_method(table, models::moments_from_text<double>(inertia_));
  const int cost = method.cost();
  const long n = steps_for_cost(cost);
  distance_to_exact observer{&exact_attitudes(n)};
  models::body_state<double> s;
  s.G = {1, 1, 1};
  models::integrate(method, s, 1.0 / static_cast<double>(n), n, observer);
  const double mean = observer.sum / static_cast<double>(n);
  // (h/C) of this run against 1/1980, to the scheme's order: 1 when C divides 1980.
  const double reduced = 1.0 / (static_cast<double>(n) * cost);
  return mean * std::pow(1.0 / (measured_best_steps_per_cost * reduced), table.order);
}

std::vector<measured_reference> measure_references(const fixed_reduced_step_protocol& protocol) {
  std::vector<measured_reference> out;
  for (const auto& base : schemes::reference_scheme_names()) {
    measured_reference best;
    best.error = std::numeric_limits<double>::infinity();
    for (const auto& perm : bch::permutation_names()) {
      const auto table = schemes::reference_scheme(base + ":" + perm);
      if (!table) throw std::logic_error("no reference scheme " + base + ":" + perm);
      const double e = protocol.error(*table);
      if (e < best.error) best = {base + ":" + perm, schemes::cost_in_rotations(*table), table->order, e};
    }
    out.push_back(best);
  }
  return out;
}

}  // namespace rotlie::runs
