#include "rotlie/runs/maps_truth.hpp"

#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {
namespace {

std::array<cln::cl_RA, 3> unit_inverse_moments(const lie::moments_of_inertia& body) {
  const auto unit = solver::scaled_to_unit_I3(body);
  return {cln::recip(unit.I[0]), cln::recip(unit.I[1]), cln::cl_RA(1)};
}

std::vector<models::remainder_term> terms_of(const lie::polynomial<double>& h5) {
  std::vector<models::remainder_term> out;
  for (const auto& [m, c] : h5.terms())
    out.push_back({{static_cast<int>(m[0]), static_cast<int>(m[1]), static_cast<int>(m[2])}, c});
  return out;
}

std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && x[order[j + 1]] == x[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = (static_cast<double>(i + j) / 2) + 1;
    i = j + 1;
  }
  return r;
}


}  // namespace

// The fastest of several runs: errors at equal CPU time go as the 4th power of this number.
double cpu_seconds_per_step(const schemes::scheme_table& table, const lie::moments_of_inertia& body) {
  return runs::cpu_seconds_per_step(table, models::moments_from_text<double>(lie::inertia_text(body)), {5, 0.01});
}

std::vector<models::remainder_term> remainder_terms(const solver::dedicated_solution& s,
                                                    const lie::moments_of_inertia& body) {
  std::map<std::string, double> values;
  for (const auto& [name, v] : s.coefficients) values[name] = cln::double_approx(v);
  return terms_of(bch::compute_numeric_modified_hamiltonian(s.layout, unit_inverse_moments(body), values, 5)[5]);
}

std::vector<models::remainder_term> reference_remainder_terms(const std::string& base, const std::string& permutation,
                                                              const lie::moments_of_inertia& body) {
  const auto table = schemes::reference_scheme(base);
  if (!table) throw std::invalid_argument("unknown reference scheme '" + base + "'");
  // The unpermuted word, laid out at the permutation (as solver::reference_analytic_remainder).
  const auto layout = bch::layout_scheme(table->word, solver::splitting_of(table->splitting), permutation);
  std::map<std::string, double> values;
  for (std::size_t k = 0; k < layout.stages.size(); ++k)
    values.emplace(layout.stages[k].coefficient, std::stod(table->stages[k].value));
  return terms_of(bch::compute_numeric_modified_hamiltonian(layout, unit_inverse_moments(body), values, 5)[5]);
}

models::remainder_prediction predict_protocol_error(const lie::moments_of_inertia& body,
                                                    const std::vector<models::remainder_term>& h5) {
  const auto unit = solver::scaled_to_unit_I3(body);
  const models::vec3<double> I{cln::double_approx(unit.I[0]), cln::double_approx(unit.I[1]), 1.0};
  return models::predict_remainder_error(I, {1, 1, 1}, 1.0, h5);  // LV section 4.1: G(0) = (1, 1, 1), T = 1
}

body_truth measure_body_truth(const lie::moments_of_inertia& body, const std::vector<std::string>& families) {
  body_truth out;
  out.body = solver::scaled_to_unit_I3(body);
  const protocol_runner runner(out.body, truth_min_level, truth_max_level, false);  // CPU timed below
  auto reference = runner.best_permutation(solver::map_reference_scheme);  // smallest measured constant
  reference.seconds_per_step = cpu_seconds_per_step(*schemes::reference_scheme(reference.name), out.body);
  out.reference = reference.name;
  out.reference_slope = reference.slope;
  const int reference_cost = solver::reference_cost(solver::map_reference_scheme);
  // The reference's predictors at their own best permutation: a predictor never looks at a measurement.
  double reference_transported = std::numeric_limits<double>::infinity(), reference_gradient = reference_transported;
  for (const auto& perm : bch::permutation_names()) {
    const auto p = predict_protocol_error(out.body, reference_remainder_terms(solver::map_reference_scheme, perm, out.body));
    reference_transported = std::min(reference_transported, p.transported);
    reference_gradient = std::min(reference_gradient, p.mean_gradient);
  }
  for (const auto& family : families) {
    family_truth f;
    f.family = family;
    const auto point = solver::compute_map_point(out.body, family);
    if (point.best && point.ratio) {
      f.best = solver::scheme_table_name(*point.best);
      f.analytic_ratio = *point.ratio;
      const auto table = solver::scheme_table_of(*point.best, out.body);
      auto curve = runner.run(table);
      curve.seconds_per_step = cpu_seconds_per_step(table, out.body);
      f.measured_ratio_h = ratio_at_equal_reduced_step(reference, curve);
      f.measured_ratio_cpu = ratio_at_equal_cpu_time(reference, curve);
      f.slope = curve.slope;
      f.measured_constant = curve.constant;
      const auto p = predict_protocol_error(out.body, remainder_terms(*point.best, out.body));
      const double scale = std::pow(static_cast<double>(reference_cost) / curve.cost, 4);
      f.predicted_ratio = reference_transported / p.transported * scale;
      f.gradient_ratio = reference_gradient / p.mean_gradient * scale;
      f.predicted_constant = p.transported * std::pow(static_cast<double>(curve.cost), 4);
    }
    out.families.push_back(std::move(f));
  }
  return out;
}

std::vector<lie::moments_of_inertia> truth_bodies(int K) {
  std::vector<lie::moments_of_inertia> out;
  for (const auto& g : solver::asymmetric_grid(K)) out.push_back(g.body);
  out.push_back(lie::parse_moments("water"));
  return out;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::invalid_argument("spearman: sizes differ");
  const std::size_t n = x.size();
  if (n < 3) return std::numeric_limits<double>::quiet_NaN();
  const auto rx = ranks(x), ry = ranks(y);
  const double mean = (static_cast<double>(n) + 1) / 2;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (rx[i] - mean) * (ry[i] - mean);
    sxx += (rx[i] - mean) * (rx[i] - mean);
    syy += (ry[i] - mean) * (ry[i] - mean);
  }
  // No spread on a side: no correlation (NaN without dividing 0 by 0, which the sanitizers trap).
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rotlie::runs
