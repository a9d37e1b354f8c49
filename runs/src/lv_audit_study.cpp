// The measurements behind the audit's computed claims (see lv_audit_study.hpp).
#include "rotlie/runs/lv_audit_study.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {
namespace {

// LV 4.1: for small angles the R^9 attitude error is √3 × the quadratic mean of the angular errors
// of the three principal axes; on small rotations (Rodrigues' formula) about a few axes.
double small_angle_worst() {
  double worst = 0;
  const std::array<std::array<double, 3>, 3> axes = {{{1, 0, 0}, {0.6, 0.8, 0}, {0.48, 0.6, 0.64}}};
  for (const auto& u : axes)
    for (const double theta : {1e-2, 1e-3}) {
      const double c = std::cos(theta), s = std::sin(theta);
      double frobenius = 0, squares = 0;
      for (int i = 0; i < 3; ++i) {
        // column i of R = c I + s [u]x + (1 - c) u u^T, and its difference from e_i
        std::array<double, 3> col{};
        for (int k = 0; k < 3; ++k) col[k] = (1 - c) * u[k] * u[i] + (k == i ? c : 0);
        const int j = (i + 1) % 3, l = (i + 2) % 3;
        col[l] += s * u[j];  // [u]x e_i = u × e_i
        col[j] -= s * u[l];
        const std::array<double, 3> d = {col[0] - (i == 0), col[1] - (i == 1), col[2] - (i == 2)};
        frobenius += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double cross = std::hypot(col[j], col[l]);  // |e_i × R e_i|
        squares += std::pow(std::atan2(cross, col[i]), 2);
      }
      worst = std::max(worst, std::abs(std::sqrt(frobenius) / (std::sqrt(3.0) * std::sqrt(squares / 3)) - 1));
    }
  return worst;
}

// LV 4.1 (from 3.1.2): the permutations at which RSRSRSR has the remainder of SRSRSRS, compared exactly
// to order 5 for water. Separately built remainders hold distinct GiNaC symbols of the same name, so the
// free coefficients get values: three rational points (a1, b1), the remainders compared exactly there.
std::string sr_equal_at() {
  const auto water = lie::parse_moments("water");
  const std::vector<std::pair<cln::cl_RA, cln::cl_RA>> points = {
      {cln::cl_RA(3) / 10, cln::cl_RA(1) / 7}, {cln::cl_RA(-2) / 9, cln::cl_RA(5) / 11}, {cln::cl_RA(7) / 13, cln::cl_RA(-1) / 3}};
  const auto remainder = [&](const std::string& scheme, const std::string& perm, const std::pair<cln::cl_RA, cln::cl_RA>& ab) {
    bch::remainder_request q;
    q.scheme = scheme;
    q.permutation = perm;
    q.order = 5;
    q.inertia = water;
    q.coefficients = {{"a1", ab.first}, {"b1", ab.second}};
    return bch::compute_remainder(q).k;
  };
  std::string equal_at;
  for (const auto& p : bch::permutation_names()) {
    bool same = true;
    for (const auto& ab : points) {
      const auto sr = remainder("SRSRSRS", "ABC", ab), rs = remainder("RSRSRSR", p, ab);
      same = same && rs.remainder.size() == sr.remainder.size();
      for (std::size_t k = 2; same && k < sr.remainder.size(); ++k) {
        auto d = rs.remainder[k];
        for (const auto& [m, c] : sr.remainder[k].terms()) d.add_term(m, -c);
        for (const auto& [m, c] : d.terms()) same = same && GiNaC::expand(c).is_zero();
      }
    }
    if (same) equal_at += (equal_at.empty() ? "" : ", ") + p;
  }
  return equal_at;
}

// LV 4.3, Fig. 5: among the ten P of smallest ‖H_R5‖ (the dedicated section's file) and P1 BAC (5), each
// solved again here and measured.
lv_audit_best_p best_p(const std::filesystem::path& file, const lie::moments_of_inertia& water, const protocol_runner& runner,
                       const schemes::scheme_table& p1_table) {
  std::ifstream in(file);
  const auto j = nlohmann::json::parse(in);
  std::vector<std::tuple<double, std::string, std::string, int>> top;  // remainder, scheme, perm, label
  for (const auto& s : j.at("solutions"))
    top.emplace_back(s.at("analytic_remainder").get<double>(), s.at("scheme"), s.at("perm"), s.at("label").get<int>());
  std::sort(top.begin(), top.end());
  lv_audit_best_p out;
  out.solutions = j.at("solutions").size();
  for (std::size_t k = 0; k < top.size(); ++k)
    if (std::get<1>(top[k]) == "P1" && std::get<2>(top[k]) == "BAC" && std::get<3>(top[k]) == 5) out.p1_rank = k + 1;
  top.resize(std::min<std::size_t>(10, top.size()));
  for (const auto& [remainder, scheme, perm, label] : top) {
    const auto sys = solver::solve_dedicated(water, {scheme}, {perm}, 40);
    const auto& s = find_solution(sys, scheme, perm, label);
    out.measured.emplace_back(runner.run(solver::scheme_table_of(s, water)).constant, s.name());
  }
  out.p1_constant = runner.run(p1_table).constant;
  if (out.p1_rank > 10) out.measured.emplace_back(out.p1_constant, "P1 BAC (5)");
  out.favourite = out.measured.front();  // the smallest ‖H_R5‖
  std::sort(out.measured.begin(), out.measured.end());
  return out;
}

}  // namespace

lv_audit_study_result lv_audit_study(const lv_audit_options& options) {
  const double start = models::thread_cpu_seconds();
  lv_audit_study_result out;
  const auto water = lie::parse_moments("water");
  const protocol_runner runner{water, 1, options.quick ? 8 : 10, false};
  auto n2 = scheme_named("N2:BAC:2", water), r4 = scheme_named("R:ABC:4", water), p1 = scheme_named("P1:BAC:5", water);

  // LV 4.1, 5.2, 5.3: the costs C/C0 behind (12/9)^4 and (12/11)^4.
  out.cost_mclachlan = schemes::cost_in_rotations(*schemes::reference_scheme("RS4-S5-McLachlan"));
  out.cost_n2 = schemes::cost_in_rotations(n2);
  out.cost_r4 = schemes::cost_in_rotations(r4);
  out.cost_p1 = schemes::cost_in_rotations(p1);

  // LV 4.1's cost model: CPU time per rotation.
  n2.name = "N2 BAC (2)", r4.name = "R ABC (4)", p1.name = "P1 BAC (5)";
  const auto I = models::moments_from_text<double>(lie::inertia_text(water));
  for (const auto& t : {n2, r4, p1, *schemes::reference_scheme("RS4-S5-McLachlan:CBA")})
    out.seconds_per_rotation.emplace_back(t.name, cpu_seconds_per_step(t, I, {3, 0.05}) / schemes::cost_in_rotations(t));

  // LV 4.3: Fassò's and Hairer-Vilmart's (0.345, 0.653, 1), and water.
  try {
    lie::parse_moments("345/1000,653/1000,1");
  } catch (const std::invalid_argument& e) {
    out.fasso_rejection = e.what();
  }
  out.water_I1 = cln::double_approx(water.I[0]), out.water_I2 = cln::double_approx(water.I[1]);

  // LV 4.2: for the spherical top R is the identity (its Hamiltonian part vanishes).
  const std::array<cln::cl_RA, 3> w = {1, 1, 1};
  out.sphere_r_zero = true;
  for (const auto& p : bch::permutation_names())
    out.sphere_r_zero = out.sphere_r_zero && bch::rational_part_hamiltonian('R', bch::splitting::rs, p, w).is_zero();
  out.sphere_s_nonzero = !bch::rational_part_hamiltonian('S', bch::splitting::rs, "ABC", w).is_zero();

  out.small_angle_worst = small_angle_worst();
  out.sr_equal_at = sr_equal_at();
  out.grid_points = solver::body_grid(200).size(), out.grid_asymmetric = solver::asymmetric_grid(200).size();

  // LV 4.3, Fig. 5: the numerically best R for water, over all its solutions.
  const auto water_r = solver::solve_dedicated(water, {"R"}, bch::permutation_names(), 40);
  for (const auto& s : water_r.solutions) out.r_measured.emplace_back(runner.run(solver::scheme_table_of(s, water)).constant, s.name());
  std::sort(out.r_measured.begin(), out.r_measured.end());
  out.r_solutions = water_r.solutions.size();
  for (std::size_t k = 0; k < water_r.solutions.size(); ++k)
    if (water_r.solutions[k].name() == "R ABC (4)") out.r_abc4_rank = k + 1;

  if (!options.solutions_water_P.empty()) {
    if (options.quick)
      out.best_p_missing = "not computed in this run (section dedicated skips P with --quick)";
    else if (!std::ifstream(options.solutions_water_P))
      out.best_p_missing = "solutions_water_P.json missing";
    else
      out.best_p = best_p(options.solutions_water_P, water, runner, p1);
  }
  out.cpu_seconds = models::thread_cpu_seconds() - start;
  return out;
}

}  // namespace rotlie::runs
