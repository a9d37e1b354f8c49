#include "rotlie/solver/dedicated_schemes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/lie/theorems.hpp"
#include "rotlie/solver/critical_points.hpp"
#include "rotlie/solver/real_solutions.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::solver {
namespace {

/// Why a system has no isolated solutions, in the body's terms: a symmetric top whose equal
/// moments remove a part of the splitting, or else a singular elimination at this body.
std::string degeneracy_reason(const lie::moments_of_inertia& body, bch::splitting split, const std::string& perm,
                              const std::string& what_vanished) {
  const auto axis = [&](int k) { return perm[static_cast<std::size_t>(k)] - 'A'; };
  const auto name = [](int i) { return "I" + std::to_string(i + 1); };
  const auto equal = [&](int i, int j) { return name(std::min(i, j)) + " = " + name(std::max(i, j)); };
  if (split == bch::splitting::rs) {
    // R = G_x²/2 (1/I_x − 1/I_y), S = G_z²/2 (1/I_z − 1/I_y) + G²/(2 I_y) with x, y, z = the permuted axes
    const int x = axis(0), y = axis(1), z = axis(2);
    const std::string gx = "G" + std::to_string(x + 1);
    if (body.I[x] == body.I[y])
      return "symmetric top (" + equal(x, y) + "): the R part " + gx + "²/2 (1/" + name(x) + " − 1/" +
             name(y) + ") vanishes, so R and S commute and no choice of coefficients changes H_R3 (" + what_vanished + ")";
    if (body.I[z] == body.I[y])
      return "symmetric top (" + equal(z, y) + "): S reduces to the rotation about G, which commutes with R (" +
             what_vanished + ")";
  }
  const std::string symmetry = lie::symmetry_of(body);
  if (!symmetry.empty()) return "symmetric top (" + symmetry + "): " + what_vanished;
  std::string flat;
  for (int k = 0; k < 3; ++k)  // eq. (77) with equality: a planar body
    if (body.I[static_cast<std::size_t>(k)] ==
        body.I[static_cast<std::size_t>((k + 1) % 3)] + body.I[static_cast<std::size_t>((k + 2) % 3)])
      flat = " on this flat body (" + name(k) + " = " + name((k + 1) % 3) + " + " + name((k + 2) % 3) + ")";
  return "the elimination is singular" + (flat.empty() ? std::string(" at this body") : flat) + ": " + what_vanished +
         " (the automatic resolution fails here, like at the isolated points of the paper's Fig. 9)";
}

}  // namespace
namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }


}  // namespace

// Eq. (64) in natural units (H = Σ G_i²/(2I_i), no 2I1 scaling) for the body scaled to I3 = 1, as in
// section 5.1 (H_R5 is homogeneous of degree −5 in the moments): this reproduces Table 4's absolute
// values (×10^-2) and Table 3's ratios.
double analytic_remainder_norm(const std::vector<double>& q) {
  double s = 0;
  for (double v : q) s += v * v;
  return std::sqrt(s);
}

lie::moments_of_inertia scaled_to_unit_I3(const lie::moments_of_inertia& body) {
  return {{body.I[0] / body.I[2], body.I[1] / body.I[2], cln::cl_RA(1)}};
}

order_conditions conditions_of(const bch::exact_modified_hamiltonian& k) {
  order_conditions c;
  c.p1 = k.remainder[3].coefficient(lie::monomial(2, 2, 0));
  c.p2 = k.remainder[3].coefficient(lie::monomial(2, 0, 2));
  if (k.remainder.size() > 5)
    for (const auto& [m, q] : k.remainder[5].terms()) c.norm_squared += q * q;
  return c;
}

family_result solve_dedicated(const lie::moments_of_inertia& body, const std::vector<std::string>& schemes,
                              const std::vector<std::string>& permutations, int digits) {
  if (digits < 10) throw std::invalid_argument("--digits must be at least 10");
  lie::validate_moments(body);
  family_result result;
  // The order conditions are homogeneous in 1/I: the body in any unit (kg m², u Å², 1e-100) has the
  // solutions of the body scaled to I3 = 1, exactly, and every number below is computed for that one.
  const lie::moments_of_inertia unit = scaled_to_unit_I3(body);
  const std::array<cln::cl_RA, 3> w{cln::recip(unit.I[0]), cln::recip(unit.I[1]), cln::cl_RA(1)};
  for (const auto& scheme : schemes) {
    const auto named = bch::find_named_scheme(scheme);
    if (!named) throw std::invalid_argument("unknown scheme '" + scheme + "'");
    for (const auto& perm : permutations) {
      lie::stop_point();
      auto t = clock_type::now();
      const auto layout = bch::layout_scheme(named->word, named->split, perm);
      const std::size_t unknowns = layout.free_coefficients.size();
      if (unknowns != 2 && unknowns != 3)
        throw std::invalid_argument(scheme + " has " + std::to_string(unknowns) +
                                    " free coefficients; this solver takes two (N) or three (R, P)");
      // H_R3 for the conditions; H_R5 as well when it is minimised (R, P), else only at each solution.
      const auto k = bch::compute_exact_modified_hamiltonian(layout, w, unknowns == 3 ? 5 : 3);
      const order_conditions conditions = conditions_of(k);
      const auto &p1 = conditions.p1, &p2 = conditions.p2;
      result.seconds_conditions += since(t);

      // Two free coefficients: H_R3 = 0 has isolated solutions. Three (R, P; section 3.4): the critical
      // points of ‖H_R5‖² (eq. 64) on the curve H_R3 = 0.
      std::vector<std::vector<cln::cl_RA>> points;
      system_report report;
      report.scheme = scheme;
      report.permutation = perm;
      if (unknowns == 2) {
        const auto sys = solve_two_equations(p1, p2, 0, 1, digits);
        result.seconds_elimination += sys.seconds_elimination;
        result.seconds_roots += sys.seconds_roots;
        report.degenerate = sys.degenerate;
        report.note = sys.note;
        report.eliminant_degree = sys.resultant_degree_u;
        for (const auto& p : sys.points) points.push_back({p.u, p.v});  // sorted by u: labels follow Tables 2 and 4
      } else {
        const auto crit = constrained_critical_points(conditions.norm_squared, p1, p2, digits);
        result.seconds_elimination += crit.seconds_elimination;
        result.seconds_roots += crit.seconds_roots;
        report.degenerate = crit.degenerate;
        report.note = crit.note;
        report.eliminant_degree = crit.eliminant_degree;
        report.eliminant_real_roots = crit.eliminant_real_roots;
        if (crit.eliminated >= 0) report.eliminated = layout.free_coefficients[static_cast<std::size_t>(crit.eliminated)];
        report.discarded = crit.discarded;
        if (crit.discarded > 0)
          report.note = std::to_string(crit.discarded) + " root(s) of the reduced system discarded: the linear solve for " +
                        report.eliminated + " is undefined there";
        for (const auto& p : crit.points) points.push_back({p.values[0], p.values[1], p.values[2]});
      }
      report.real_solutions = static_cast<int>(points.size());
      if (report.degenerate) report.note = degeneracy_reason(body, named->split, perm, report.note);
      t = clock_type::now();
      const cln::cl_RA accuracy = cln::recip(cln::expt(cln::cl_RA(10), digits + 10));
      int label = 0;
      for (const auto& point : points) {
        dedicated_solution s;
        s.scheme = scheme;
        s.permutation = perm;
        s.label = ++label;
        s.layout = layout;
        s.free = layout.free_coefficients;
        std::map<std::string, double> numeric;
        for (const auto& st : layout.stages) {
          if (numeric.count(st.coefficient) != 0) continue;
          const auto& expression = k.coefficient_values.at(st.coefficient);
          if (expression.is_constant()) s.exact.push_back(st.coefficient);
          // Within the solution's accuracy of 0 is 0: a table never prints 1e-450 for a vanishing stage.
          const cln::cl_RA value = expression(point);
          s.coefficients.emplace_back(st.coefficient, cln::abs(value) < accuracy ? cln::cl_RA(0) : value);
          numeric[st.coefficient] = cln::double_approx(s.coefficients.back().second);
        }
        // No solution leaves the solver unless its table can say `order 4`: the conditions vanish
        // relative to the size of their terms at the decimals a table of `digits` digits writes.
        const auto certificate = certify_order_four(layout, unit, written_coefficients(s, digits), digits);
        if (certificate.order < 4) {
          --label;
          ++report.uncertified;
          report.note += std::string(report.note.empty() ? "" : "; ") + "a root dropped, not order 4 at " +
                         std::to_string(digits) + " digits: " + certificate.failure;
          continue;
        }
        s.residual = certificate.residual;
        std::vector<double> q;
        if (unknowns == 3) {
          std::vector<double> x;
          for (const auto& v : point) x.push_back(cln::double_approx(v));
          for (const auto& [m, coefficient] : k.remainder[5].terms()) q.push_back(coefficient.evaluate(x));
        } else {
          const auto h = bch::compute_numeric_modified_hamiltonian(layout, w, numeric, 5);
          for (const auto& [m, coefficient] : h[5].terms()) q.push_back(coefficient);
        }
        s.analytic_remainder = analytic_remainder_norm(q);
        result.solutions.push_back(std::move(s));
      }
      report.real_solutions -= report.uncertified;
      result.seconds_remainder += since(t);
      result.systems.push_back(std::move(report));
    }
  }
  std::stable_sort(result.solutions.begin(), result.solutions.end(),
                   [](const auto& a, const auto& b) { return a.analytic_remainder < b.analytic_remainder; });
  return result;
}

}  // namespace rotlie::solver
