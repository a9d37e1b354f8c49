// The measurements of van Zon & Schofield's sections V.A-B: every run of the report's section
// "van Zon & Schofield", with the dedicated free rotors of Laskar & Vaillant beside the paper's integrators.
#include "rotlie/runs/vzs_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/order_fit.hpp"
#include "rotlie/models/scenes/water.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/schemes/quad.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "md_experiments.hpp"

namespace rotlie::runs {

namespace {

struct row {
  vzs_integrator shown;
  const schemes::scheme_table* rotor = nullptr;
};

// The dedicated rotors solved for the water molecule (the body of the scenes, exact ratios).
struct dedicated_rotors {
  std::map<std::string, schemes::scheme_table> tables;
  dedicated_rotors() {
    const auto water = lie::parse_moments(models::water::moments_ratio);
    for (const char* name : {"N2:BAC:2", "P1:BAC:5", "R:ABC:4"}) tables.emplace(name, scheme_named(name, water));
  }
  row sier2(const std::string& key) const { return {{"SIER2/" + key, "SIER2/" + key, ""}, &tables.at(key)}; }
};

std::vector<row> all_rows(const dedicated_rotors& d) {
  return {{{"MRDL", "MRDL", "MRDL"}},
          {{"MRDL-reversed", "MRDL-reversed", "MRDL"}},
          {{"SEJ4 (reconstruction)", "SEJ4", "SEJ4"}},
          {{"SIER2", "SIER2", "SIER2"}},
          {{"SIER4", "SIER4", "SIER4"}},
          d.sier2("N2:BAC:2"),
          d.sier2("P1:BAC:5"),
          d.sier2("R:ABC:4"),
          {{"SIER2/RS4-S5-McLachlan:CBA", "SIER2/RS4-S5-McLachlan:CBA", ""}},
          {{"SIER2/ABCBA4-SS3-Yoshida", "SIER2/ABCBA4-SS3-Yoshida", ""}}};
}

models::md_run_options run_options(const row& r, double h, double T, long runs) {
  models::md_run_options o;
  o.integrator = method_named(r.shown.name, method_system::md).splitting;  // the program's own names; X solved into r.rotor
  o.rotor_table = r.rotor;
  o.h_fs = h;
  o.T_ps = T;
  o.runs = runs;
  o.seed = 1;
  return o;
}

// SIER2's δ is round-off only: its free-water run at h = 1.66 fs in the scalar T.
template <class T>
models::free_water_result sier2_roundoff(double T_ps, long runs) {
  return models::run_free_water(models::free_water<T>{}, run_options({{"SIER2", "SIER2", "SIER2"}}, 1.66, T_ps, runs));
}

// E[∏ G_i^{n_i}] for independent G_i ~ N(0, s_i): ∏ s_i^{n_i/2} (n_i − 1)!! (0 for an odd n_i).
double gaussian_moment(const std::array<unsigned, 3>& n, const std::array<double, 3>& s) {
  double m = 1;
  for (std::size_t i = 0; i < 3; ++i) {
    if (n[i] % 2) return 0;
    for (unsigned k = 1; k < n[i]; k += 2) m *= k * s[i];
  }
  return m;
}

// H_R3 of the table ABCBA2:perm (the rotor of MRDL or MRDL-reversed) for water scaled to I3 = 1, by
// the BCH expansion at the table's own coefficients, and its size over the canonical momenta
// (G_i ~ N(0, I_i), k_B T = 1: only ratios between the orders are used).
vzs_remainder_size leapfrog_remainder(const std::string& perm) {
  const auto unit = solver::scaled_to_unit_I3(lie::parse_moments(models::water::moments_ratio));
  const std::array<cln::cl_RA, 3> w{cln::recip(unit.I[0]), cln::recip(unit.I[1]), cln::cl_RA(1)};
  const auto table = *schemes::reference_scheme("ABCBA2:" + perm);
  const auto layout = bch::layout_scheme("ABCBA", bch::splitting::abc, perm);
  std::map<std::string, double> values;
  for (std::size_t i = 0; i < layout.stages.size(); ++i) values[layout.stages[i].coefficient] = std::stod(table.stages[i].value);
  const auto H3 = bch::compute_numeric_modified_hamiltonian(layout, w, values, 3).at(3);
  const std::array<double, 3> s{cln::double_approx(unit.I[0]), cln::double_approx(unit.I[1]), 1.0};
  vzs_remainder_size r;
  double mean = 0, square = 0, gradient = 0;
  for (const auto& [m, c] : H3.terms()) {
    r.norm += c * c;
    mean += c * gaussian_moment({m[0], m[1], m[2]}, s);
    for (const auto& [m2, c2] : H3.terms()) {
      square += c * c2 * gaussian_moment({m[0] + m2[0], m[1] + m2[1], m[2] + m2[2]}, s);
      for (int k = 0; k < 3; ++k) {
        if (m[k] == 0 || m2[k] == 0) continue;
        std::array<unsigned, 3> n{m[0] + m2[0], m[1] + m2[1], m[2] + m2[2]};
        n[static_cast<std::size_t>(k)] -= 2;
        gradient += c * c2 * m[k] * m2[k] * gaussian_moment(n, s);
      }
    }
  }
  r.norm = std::sqrt(r.norm);
  r.fluctuation = std::sqrt(std::max(0.0, square - mean * mean));
  r.gradient = std::sqrt(gradient);
  return r;
}

// CPU ns per molecule-step on the dipole scene (64 molecules, h/f = 4.2 fs), the least of `rounds`
// interleaved timings of `seconds` each, so that a load from elsewhere on the machine inflates none.
std::vector<double> step_costs(const std::vector<row>& rows, double seconds, int rounds,
                               const std::function<void(const std::string&)>& progress) {
  const models::dipole_field<double> scene;
  constexpr int molecules = 64;
  std::vector<double> best(rows.size(), std::numeric_limits<double>::infinity());
  for (int round = 0; round < rounds; ++round)
    for (std::size_t k = 0; k < rows.size(); ++k) {
      progress("cost, " + rows[k].shown.label);
      const auto o = run_options(rows[k], 4.2, 1, 1);
      const double h = 4.2 * method_named(rows[k].shown.name, method_system::md).splitting.f;
      best[k] = std::min(best[k], models::with_scene_integrator<double>(scene, o, [&](const auto& method) {
        models::rigid_bodies_state<double> x;
        for (int n = 0; n < molecules; ++n) x.bodies.push_back(scene.initial(1, static_cast<std::uint64_t>(n)).bodies[0]);
        method.step(x, h);  // sizes the force vectors
        long steps = 0;
        const double c0 = models::thread_cpu_seconds();
        double used = 0;
        while (used < seconds) {
          for (int i = 0; i < 100; ++i) method.step(x, h);
          steps += 100;
          used = models::thread_cpu_seconds() - c0;
        }
        return 1e9 * used / (static_cast<double>(steps) * molecules);
      }));
    }
  return best;
}

}  // namespace

vzs_budget vzs_budget_for(bool quick) {
  if (quick) return {100, 5, 50, 20, 8, 10, 200, 20, 2, 2, 0.02, 2};
  return {400, 5, 200, 100, 20, 20, 1000, 100, 10, 4, 0.1, 5};
}

double growth_exponent(const models::free_water_result& r) {
  // δ against t in the one fit's terms: t in place of h, every positive sample of the second half
  std::vector<models::protocol_point> points;
  for (std::size_t j = r.t_ps.size() / 2; j < r.t_ps.size(); ++j)
    if (r.delta[j] > 0) points.push_back({r.t_ps[j], r.t_ps[j], r.delta[j], 0});
  models::fit_rule every;
  every.margin = 0;
  return models::fitted_order(points, every);
}

vzs_study_result vzs_study(const vzs_budget& b, const std::function<void(const std::string&)>& progress_sink) {
  const auto progress = [&](const std::string& line) {
    if (progress_sink) progress_sink(line);
  };
  vzs_study_result out;
  progress("solving the dedicated rotors for water");
  const dedicated_rotors dedicated;
  const auto rows = all_rows(dedicated);
  for (const auto& r : rows) {
    out.integrators.push_back(r.shown);
    out.integrators.back().f = method_named(r.shown.name, method_system::md).splitting.f;
  }

  // V.A: τ at h = 1.66 and 8 fs
  for (const auto& r : rows) {
    progress("tau, " + r.shown.label);
    auto& tau = out.tau.emplace_back();
    for (std::size_t k = 0; k < 2; ++k)
      tau[k] = models::run_free_water(models::free_water<double>{}, run_options(r, k == 0 ? 1.66 : 8, b.tau_T_ps, b.tau_runs));
  }

  // SIER2's round-off in three scalars
  const auto roundoff = [&](const std::string& scalar, models::free_water_result run, models::free_water_result at10, double eps) {
    const double p = growth_exponent(run);
    out.roundoff.push_back({scalar, std::move(run), std::move(at10), eps, p});
  };
  progress("SIER2 round-off in double");
  {
    auto run = sier2_roundoff<double>(b.roundoff_double_T_ps, b.roundoff_runs);
    auto at10 = sier2_roundoff<double>(10, b.roundoff_runs);
    roundoff("double", std::move(run), std::move(at10), std::numeric_limits<double>::epsilon() / 2);
  }
  progress("SIER2 round-off in long double");
  {
    auto run = sier2_roundoff<long double>(b.roundoff_long_double_T_ps, b.roundoff_runs);
    auto at10 = sier2_roundoff<long double>(10, b.roundoff_runs);
    roundoff("long double", std::move(run), std::move(at10), std::numeric_limits<long double>::epsilon() / 2);
  }
  progress("SIER2 round-off in float128");
  {
    const auto q = sier2_roundoff<quad>(b.roundoff_float128_T_ps, b.roundoff_runs);
    roundoff("float128", q, q, static_cast<double>(std::numeric_limits<quad>::epsilon() / 2));
  }

  // V.B: Table I over the first five integrators (the paper's)
  const std::vector<row> table_rows(rows.begin(), rows.begin() + 5);
  const char* const h_text[] = {"4.2", "11", "21"};
  for (std::size_t k = 0; k < 3; ++k)
    for (const auto& r : table_rows) {
      progress(std::string("Table I, h/f = ") + h_text[k] + " fs, " + r.shown.label);
      const int f = method_named(r.shown.name, method_system::md).splitting.f;
      const auto res = models::run_dipole_field(models::dipole_field<double>{},
                                                run_options(r, out.table_h_over_f[k] * f, b.table_T_ps, b.table_runs));
      out.table[k].push_back({res.dH, res.dLz});
    }

  out.mrdl_remainder = leapfrog_remainder("ABC");
  out.reversed_remainder = leapfrog_remainder("CBA");

  // accuracy against cost, failure
  out.grid = {1, 2, 4.2, 8, 11, 16, 21, 32, 45, 64};
  for (const auto& r : rows) {
    progress("accuracy against cost, " + r.shown.label);
    const int f = method_named(r.shown.name, method_system::md).splitting.f;
    auto& s = out.scan.emplace_back();
    bool dipole_ok = true, free_ok = true;
    for (double x : out.grid) {
      const auto d = models::run_dipole_field(models::dipole_field<double>{}, run_options(r, x * f, b.scan_T_ps, b.scan_runs));
      const bool works = d.failed_runs == 0 && d.dH.mean <= out.energy_limit;
      if (d.failed_runs == 0 && d.dH.mean > 0)
        s.dipole_h.push_back(x), s.dipole_cpu.push_back(d.cpu_s_per_ps), s.dipole_error.push_back(d.dH.mean);
      dipole_ok = dipole_ok && works;
      if (dipole_ok) s.last_dipole = x;
      const auto fr = models::run_free_water(models::free_water<double>{},
                                             run_options(r, x * f, std::max(b.scan_T_ps / 4, 4 * x * f / 1000), b.scan_runs));
      const double rate = 1 / fr.tau_ps;
      if (std::isfinite(rate)) s.free_h.push_back(x), s.free_cpu.push_back(fr.cpu_s_per_ps), s.free_rate.push_back(rate);
      free_ok = free_ok && fr.finite && fr.tau_ps >= out.tau_limit;
      if (free_ok) s.last_free = x;
    }
  }

  out.cost_ns = step_costs(rows, b.cost_seconds, b.cost_rounds, progress);
  return out;
}

}  // namespace rotlie::runs
