// Report section "Audit of the paper's statements" (LV sections 4 and 5): one table, every
// statement next to rotlie's number from this run and a verdict. Claims on the files of earlier
// sections are audit_file_claims.cpp's; the claims below are measured here through the library
// (cheap: exact rationals, costs, timings, the R family and a few P systems for water, ~3 s of CPU).
#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/remainder_request.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/integrate.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/reports/audit_claim.hpp"
#include "rotlie/reports/audit_table.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::reports {

// From the runs library (rotlie::runs):
using runs::find_solution;
using runs::protocol_runner;

namespace {

// What the claims below measure: the water molecule's N2 BAC (2), R and P1 BAC (5) solved here,
// the accuracy protocol, and the four schemes whose CPU time per rotation is compared.
struct library_results {
  const report_options& options;
  lie::moments_of_inertia water = lie::parse_moments("water");
  solver::family_result water_n = solver::solve_dedicated(water, {"N2"}, {"BAC"}, 40);
  solver::family_result water_r = solver::solve_dedicated(water, {"R"}, bch::permutation_names(), 40);
  solver::family_result p1_bac = solver::solve_dedicated(water, {"P1"}, {"BAC"}, 40);
  protocol_runner runner{water, 1, options.quick ? 8 : 10, false};

  explicit library_results(const report_options& o) : options(o) {}
  bool ran(const std::string& section) const {
    return options.sections.empty() || std::count(options.sections.begin(), options.sections.end(), section);
  }
  schemes::scheme_table table(const solver::family_result& family, const std::string& scheme, const std::string& perm, int label) const {
    return solver::scheme_table_of(find_solution(family, scheme, perm, label), water);
  }
};

using claim = audit_claim<library_results>;
using outcome = claim_outcome;

// LV 4.1, 5.2, 5.3: the costs C/C0 behind (12/9)^4 and (12/11)^4.
outcome costs(library_results& lib) {
  const int m = schemes::cost_in_rotations(*schemes::reference_scheme("RS4-S5-McLachlan"));
  const int n = schemes::cost_in_rotations(lib.table(lib.water_n, "N2", "BAC", 2));
  const int r = schemes::cost_in_rotations(lib.table(lib.water_r, "R", "ABC", 4));
  const int p = schemes::cost_in_rotations(lib.table(lib.p1_bac, "P1", "BAC", 5));
  return outcome::measured(m == 12 && n == 9 && p == 11 && r == 10,
                           "RS4 S5 McLachlan " + std::to_string(m) + ", N2 BAC (2) " + std::to_string(n) + ", P1 BAC (5) " +
                               std::to_string(p) + ", R ABC (4) (9 stages RS) " + std::to_string(r));
}

// Process CPU time (std::clock) per step of a table on the double stepper from G(0) = (1, 1, 1)
// at h = 1/64: the fastest of three runs of at least 0.05 s each.
double cpu_per_step(const schemes::scheme_table& t, const models::vec3<double>& I) {
  const auto method = models::free_body_method(t, I);
  double best = std::numeric_limits<double>::infinity();
  for (int repeat = 0; repeat < 3; ++repeat) {
    models::body_state<double> s;
    s.G = {1, 1, 1};
    long steps = 0;
    const std::clock_t start = std::clock();
    double cpu = 0;
    do {
      steps += models::integrate(method, s, 1.0 / 64, 1024);
      cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    } while (cpu < 0.05);
    volatile double sink = s.G[0];
    (void)sink;
    best = std::min(best, cpu / static_cast<double>(steps));
  }
  return best;
}

// LV 4.1's cost model: every rotation costs the same C0, so a step costs its count of rotations.
outcome cost_model(library_results& lib) {
  auto n2 = lib.table(lib.water_n, "N2", "BAC", 2);
  auto r4 = lib.table(lib.water_r, "R", "ABC", 4);
  auto p1 = lib.table(lib.p1_bac, "P1", "BAC", 5);
  n2.name = "N2 BAC (2)", r4.name = "R ABC (4)", p1.name = "P1 BAC (5)";
  const std::vector<schemes::scheme_table> timed = {n2, r4, p1, *schemes::reference_scheme("RS4-S5-McLachlan:CBA")};
  const auto I = models::moments_from_text<double>(lie::inertia_text(lib.water));
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  std::string v;
  for (const auto& t : timed) {
    const double per_rotation = cpu_per_step(t, I) / schemes::cost_in_rotations(t);
    lo = std::min(lo, per_rotation), hi = std::max(hi, per_rotation);
    v += (v.empty() ? "" : ", ") + t.name + " " + runs::fixed_text(per_rotation * 1e9, 1) + " ns";
  }
  return outcome::measured(hi <= 1.25 * lo,
                           "per rotation: " + v + " (spread " + runs::fixed_text(hi / lo, 2) + "×; process CPU time, double stepper)");
}

// LV 4.3: Fassò's and Hairer-Vilmart's (0.345, 0.653, 1) is no physical body.
outcome fasso_moments(library_results&) {
  std::string why;
  try {
    lie::parse_moments("345/1000,653/1000,1");
  } catch (const std::invalid_argument& e) {
    why = e.what();
  }
  return outcome::measured(!why.empty(), why.empty() ? "accepted as a body" : "rejected: " + why);
}

// LV 4.3: water (10220/29376, 19187/29376, 1) ≃ (0.348, 0.653, 1).
outcome water_moments(library_results& lib) {
  const double I1 = cln::double_approx(lib.water.I[0]), I2 = cln::double_approx(lib.water.I[1]);
  return outcome::measured(runs::fixed_text(I1, 3) == "0.348" && runs::fixed_text(I2, 3) == "0.653",
                           "rotlie's \"water\": (" + runs::fixed_text(I1, 5) + ", " + runs::fixed_text(I2, 5) + ", 1)");
}

// LV 4.2: for the spherical top R is the identity (its Hamiltonian part vanishes).
outcome sphere_rs_trivial(library_results&) {
  const std::array<cln::cl_RA, 3> w = {1, 1, 1};
  bool all_zero = true;
  for (const auto& p : bch::permutation_names())
    all_zero = all_zero && bch::rational_part_hamiltonian('R', bch::splitting::rs, p, w).is_zero();
  const bool s_nonzero = !bch::rational_part_hamiltonian('S', bch::splitting::rs, "ABC", w).is_zero();
  return outcome::measured(all_zero && s_nonzero, std::string("R part ") + (all_zero ? "= 0" : "≠ 0") + " for every permutation; S part " +
                                                      (s_nonzero ? "≠ 0" : "= 0"));
}

// LV 4.1: for small angles the R^9 attitude error is √3 × the quadratic mean of the angular errors
// of the three principal axes. Checked on small rotations (Rodrigues' formula) about a few axes.
outcome small_angle_error(library_results&) {
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
  return outcome::measured(worst < 1e-4, "largest relative difference " + runs::significant_text(worst, 2));
}

// LV 4.1 (from 3.1.2): RSRSRSR with I1 and I3 swapped (permutation CBA) has the remainder of
// SRSRSRS at every order, so SR schemes need not be considered. Compared exactly to order 5 for
// water.
outcome sr_schemes_redundant(library_results&) {
  const auto water = lie::parse_moments("water");
  // Separately built remainders hold distinct GiNaC symbols of the same name, so the free
  // coefficients get values: three rational points (a1, b1), the remainders compared exactly there.
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
  return outcome::measured(equal_at == "CBA", "equal at permutation(s): " + (equal_at.empty() ? std::string("none") : equal_at) +
                                                  " (checked to order 5)");
}

// LV 5.1: the grid of 40,401 points, symmetric tops skipped.
outcome body_grid_size(library_results&) {
  const auto all = solver::body_grid(200).size(), asymmetric = solver::asymmetric_grid(200).size();
  return outcome::measured(all == 40401, std::to_string(all) + " points, " + std::to_string(asymmetric) + " computed after skipping " +
                                             std::to_string(all - asymmetric) + " symmetric tops");
}

// LV 4.3, Fig. 5: the numerically best R for water, over all 46 solutions.
outcome best_r(library_results& lib) {
  std::vector<std::pair<double, std::string>> ranked;
  for (const auto& s : lib.water_r.solutions) ranked.emplace_back(lib.runner.run(solver::scheme_table_of(s, lib.water)).constant, s.name());
  std::sort(ranked.begin(), ranked.end());
  std::size_t analytic_rank = 0;
  for (std::size_t k = 0; k < lib.water_r.solutions.size(); ++k)
    if (lib.water_r.solutions[k].name() == "R ABC (4)") analytic_rank = k + 1;
  const std::string second =
      ranked.size() > 1 ? "; next " + ranked[1].second + " at " + runs::fixed_text(ranked[1].first / ranked[0].first, 2) + "×" : "";
  return outcome::measured(!ranked.empty() && ranked[0].second == "R ABC (4)",
                           "best of " + std::to_string(ranked.size()) + ": " + ranked[0].second + second + "; R ABC (4) is #" +
                               std::to_string(analytic_rank) + " by ‖H_R5‖");
}

// LV 4.3, Fig. 5: among the P with the smallest analytic remainders the numerically best is
// P1 BAC (5). The ranking comes from the dedicated section's solutions_water_P.json; the ten
// systems involved are solved again here to integrate them.
outcome best_p(library_results& lib) {
  if (lib.options.quick) return outcome::missing("not computed in this run (section dedicated skips P with --quick)");
  std::ifstream in(lib.options.out_dir / "solutions_water_P.json");
  if (!in) return outcome::missing("solutions_water_P.json missing");
  const auto j = nlohmann::json::parse(in);
  std::vector<std::tuple<double, std::string, std::string, int>> top;  // remainder, scheme, perm, label
  for (const auto& s : j.at("solutions"))
    top.emplace_back(s.at("analytic_remainder").get<double>(), s.at("scheme"), s.at("perm"), s.at("label").get<int>());
  std::sort(top.begin(), top.end());
  std::size_t p1_rank = 0;
  for (std::size_t k = 0; k < top.size(); ++k)
    if (std::get<1>(top[k]) == "P1" && std::get<2>(top[k]) == "BAC" && std::get<3>(top[k]) == 5) p1_rank = k + 1;
  top.resize(std::min<std::size_t>(10, top.size()));
  std::vector<std::pair<double, std::string>> measured;
  for (const auto& [remainder, scheme, perm, label] : top) {
    const auto sys = solver::solve_dedicated(lib.water, {scheme}, {perm}, 40);
    const auto& s = find_solution(sys, scheme, perm, label);
    measured.emplace_back(lib.runner.run(solver::scheme_table_of(s, lib.water)).constant, s.name());
  }
  const double p1 = lib.runner.run(lib.table(lib.p1_bac, "P1", "BAC", 5)).constant;
  if (p1_rank > 10) measured.emplace_back(p1, "P1 BAC (5)");
  const auto favourite = measured.front();  // the smallest ‖H_R5‖
  std::sort(measured.begin(), measured.end());
  return outcome::measured(measured[0].second == "P1 BAC (5)",
                           "best: " + measured[0].second + "; P1 BAC (5) is #" + std::to_string(p1_rank) + " of " +
                               std::to_string(j.at("solutions").size()) + " by ‖H_R5‖; the analytic favourite " + favourite.second +
                               " is " + runs::fixed_text(favourite.first / p1, 2) + "× less accurate than P1 BAC (5)");
}

// id, statement (LV), where, tolerance, sections read, measurement.
const std::vector<claim>& computed_claims() {
  static const std::vector<claim> claims = {
      {"small-angle-error",
       "For small angles the R^9 attitude error is √3 × the quadratic mean of the angular errors of the three principal axes", "4.1",
       "relative difference below 1e-4 for rotations of 1e-2 and 1e-3 rad about three axes", {}, small_angle_error},
      {"sr-schemes-redundant",
       "RSRSRSR with the parts of I1 and I3 exchanged has the remainder of SRSRSRS at every order, so SR schemes need not be "
       "considered",
       "4.1 (from 3.1.2)",
       "H_R2 … H_R5 of RSRSRSR equal SRSRSRS's (ABC) exactly at permutation CBA only (water; three rational (a1, b1))", {},
       sr_schemes_redundant},
      {"water-moments", "Water: I1 = 10220/29376 ≃ 0.348, I2 = 19187/29376 ≃ 0.653, I3 = 1", "4.3", "rounded to 3 decimals", {},
       water_moments},
      {"fasso-moments", "The moments (0.345, 0.653, 1) used by Fassò (2003) and Hairer and Vilmart (2006) are not a physical body",
       "4.3", "lie::parse_moments rejects them (I1 + I2 = 0.998 < I3)", {}, fasso_moments},
      {"sphere-rs-trivial", "Spherical top: the RS schemes are trivial, R reduces to the identity", "4.2",
       "the R part of the Hamiltonian is exactly 0 at I = (1, 1, 1) for all six permutations", {}, sphere_rs_trivial},
      {"costs",
       "Costs: RS4 S5 McLachlan 12 C0, an N integrator 9 C0, a P integrator 11 C0 (an RS scheme of N stages costs N + 1)",
       "4.1, 5.2, 5.3", "rotations per step of rotlie's tables equal to these", {}, costs},
      {"cost-model", "Cost model: every rotation costs the same C0, so a step costs its number of rotations (RS: stages + 1)", "4.1",
       "CPU time per rotation (per step / C) of N2 BAC (2), R ABC (4), P1 BAC (5) and RS4 S5 McLachlan within a factor 1.25", {},
       cost_model},
      {"water-best-r", "Water: the numerically best integrator R is R ABC (4)", "4.3, Fig. 5",
       "smallest error/(h/C)^4 among all R solutions for water", {}, best_r},
      {"water-best-p", "Water: among the P integrators of smallest analytic remainder, the numerically best is P1 BAC (5)",
       "4.3, Fig. 5", "smallest error/(h/C)^4 among the 10 P of smallest ‖H_R5‖ (and P1 BAC (5))", {"dedicated"}, best_p},
      {"body-grid", "The triangle ESA is sampled by a grid of 40,401 points, symmetric tops skipped", "5.1",
       "rotlie's --grid 200 has 40,401 points", {}, body_grid_size},
  };
  return claims;
}

std::string cell(std::string s) {
  for (auto& c : s)
    if (c == '|') c = '/';
  return s;
}

}  // namespace

report_section audit_section(const report_options& options) {
  if (options.progress) options.progress("Audit: the paper's statements (LV sections 4 and 5)");
  report_section s;
  s.title = "Audit of the paper's statements";
  const std::clock_t start = std::clock();

  audit_inputs in;
  in.folder = options.out_dir;
  in.maps_folder = options.maps_dir;
  in.quick = options.quick;
  for (const auto& key : report_section_keys())
    if (options.sections.empty() || std::count(options.sections.begin(), options.sections.end(), key)) in.sections_run.insert(key);
  auto rows = audit_rows_from_reports(in);

  library_results lib(options);
  const auto computed = evaluate_claims(computed_claims(), lib);
  rows.insert(rows.begin(), computed.begin(), computed.end());
  const double cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;

  std::filesystem::create_directories(options.out_dir / "audit");
  write_file_atomically(options.out_dir / "audit" / "audit.csv", audit_csv(rows));
  write_file_atomically(options.out_dir / "audit" / "audit.json", audit_json(rows).dump(2) + "\n");
  s.files = {options.out_dir / "audit" / "audit.csv", options.out_dir / "audit" / "audit.json"};

  int counts[4] = {0, 0, 0, 0};
  for (const auto& r : rows) ++counts[static_cast<int>(r.verdict)];
  std::ostringstream md;
  md << "## " << s.title << " (LV sections 4 and 5)\n\n"
     << "Each statement of Laskar & Vaillant (2018), sections 4 and 5, paraphrased with its number, next to rotlie's own number from "
        "this run: either computed here through the library or read from the files the earlier sections of this run wrote "
        "(accuracy curves, solver solutions, maps, measured map ratios). A row whose section did not run in this run says so and "
        "shows no number. Tolerances are per row; \"about N times\" is read as within 20 %. Files: [audit/audit.csv](audit/audit.csv), "
        "[audit/audit.json](audit/audit.json).\n\n"
     << counts[0] << " statements hold, " << counts[1] << " do not hold, " << counts[2] + counts[3]
     << " are not checked in this run. The audit's own computations took " << runs::fixed_text(cpu, 1) << " s of CPU time.\n\n"
     << "| statement (LV) | where | rotlie (this run) | tolerance | verdict |\n|:--|:--|:--|:--|:--|\n";
  for (const auto& r : rows)
    md << "| " << cell(r.statement) << " | " << cell(r.where) << " | " << cell(r.value) << " | " << cell(r.tolerance) << " | "
       << (r.verdict == audit_verdict::does_not_hold ? "**does not hold**" : cell(verdict_text(r))) << " |\n";
  md << "\n";
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
