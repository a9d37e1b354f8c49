// The van Zon & Schofield integrators on the dipole scene (one water molecule per body, 1.84 D in
// 2.7 MV/m): CPU ns per molecule-step of each integrator, as a ratio to MRDL measured in the same
// run (vZS: SIER2 1.7–2.0 × MRDL, SEJ4 another 1.2 ×; MRDL-reversed is MRDL with the axis order
// reversed, the same cost), and Boost.Odeint's runge_kutta_fehlberg78 at
// the CPU time of 10⁶ SIER2 steps: energy and L_z errors side by side.
// MRDL is registered first: the ratios divide by its time in this process.
#include <benchmark/benchmark.h>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <map>

#include "rotlie/models/experiments/md_experiment.hpp"
#include "rotlie/models/scenes/dipole_field.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace {

using namespace rotlie;
using models::thread_cpu_seconds;

constexpr int molecules = 64;
constexpr double h_over_f = 4.2;  // fs, Table I's first row

std::map<std::string, double>& measured_ns() {
  static std::map<std::string, double> ns;
  return ns;
}

// Dedicated rotors solved once for the scene's water molecule.
const schemes::scheme_table* dedicated(const std::string& key) {
  static std::map<std::string, schemes::scheme_table> tables;
  if (key.empty()) return nullptr;
  if (!tables.count(key)) {
    const auto water = lie::parse_moments(models::water::moments_ratio);
    const auto first = key.find(':'), second = key.rfind(':');
    const std::string scheme = key.substr(0, first), perm = key.substr(first + 1, second - first - 1);
    const auto r = solver::solve_dedicated(water, {scheme}, {perm}, 40);
    tables.emplace(key, solver::scheme_table_of(runs::find_solution(r, scheme, perm, std::stoi(key.substr(second + 1))), water));
  }
  return &tables.at(key);
}

void md_step(benchmark::State& state, const std::string& name, const std::string& dedicated_key) {
  const models::dipole_field<double> scene;
  models::md_run_options o;
  o.integrator = runs::method_named(dedicated_key.empty() ? name : "SIER2/" + dedicated_key, runs::method_system::md).splitting;
  o.rotor_table = dedicated(dedicated_key);
  const int f = o.integrator.f;
  const double h = h_over_f * f;
  models::with_scene_integrator<double>(scene, o, [&](const auto& method) {
    models::rigid_bodies_state<double> x;
    for (int k = 0; k < molecules; ++k) x.bodies.push_back(scene.initial(1, static_cast<std::uint64_t>(k)).bodies[0]);
    method.step(x, h);  // size the force vectors outside the timed loop
    const double c0 = thread_cpu_seconds();
    for (auto _ : state) {
      method.step(x, h);
      benchmark::DoNotOptimize(x.bodies.data());
    }
    const double ns = 1e9 * (thread_cpu_seconds() - c0) / (static_cast<double>(state.iterations()) * molecules);
    measured_ns()[o.integrator.name] = ns;
    state.counters["ns_per_molecule_step"] = ns;
    state.counters["ns_per_molecule_fs"] = ns / h;  // cost per simulated fs at h/f = 4.2 fs
    if (measured_ns().count("MRDL")) state.counters["x_MRDL_per_step"] = ns / measured_ns()["MRDL"];
    return 0;
  });
}

// --- Boost.Odeint on the same molecule ------------------------------------------------------------

using ode_state = std::array<double, 12>;  // Q row-major, then G

struct dipole_rhs {
  models::vec3<double> I;
  const models::dipole_field<double>* scene;
  void operator()(const ode_state& x, ode_state& dx, double) const {
    std::vector<models::rigid_body_state<double>> b(1);
    for (std::size_t i = 0; i < 9; ++i) b[0].rot.Q.a[i] = x[i];
    for (std::size_t i = 0; i < 3; ++i) b[0].rot.G[i] = x[9 + i];
    models::body_state<double> ds;
    models::euler_rhs(I, b[0].rot, ds);
    thread_local std::vector<models::vec3<double>> F(1), tau(1);
    scene->potential.evaluate(b, F, tau);
    const auto tb = transpose(b[0].rot.Q) * tau[0];
    const double k = models::real_units::ftm2v<double>();
    for (std::size_t i = 0; i < 9; ++i) dx[i] = ds.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) dx[9 + i] = ds.G[i] + k * tb[i];
  }
};

struct conserved {
  double H, Lz;
};

conserved of(const ode_state& x, const models::dipole_field<double>& scene) {
  std::vector<models::rigid_body_state<double>> b(1);
  for (std::size_t i = 0; i < 9; ++i) b[0].rot.Q.a[i] = x[i];
  for (std::size_t i = 0; i < 3; ++i) b[0].rot.G[i] = x[9 + i];
  std::vector<models::vec3<double>> F(1), tau(1);
  const double V = scene.potential.evaluate(b, F, tau);
  const double K = models::real_units::mvv2e<double>() * models::kinetic_energy(scene.moments, b[0].rot.G);
  return {K + V, models::lab_spin(b[0])[2]};
}

// Max |H − H₀|/rms(V − ⟨V⟩) and max |L_z − L_z₀|/|L_z₀| over a run, for one molecule.
struct run_errors {
  double energy = 0, lz = 0, cpu = 0;
  long steps = 0;
};

void odeint_at_equal_cpu(benchmark::State& state) {
  const models::dipole_field<double> scene;
  const auto start = scene.initial(1, 0);
  const long sier2_steps = 1'000'000;
  const double h = 4.2;
  ode_state x0{};
  for (std::size_t i = 0; i < 9; ++i) x0[i] = start.bodies[0].rot.Q.a[i];
  for (std::size_t i = 0; i < 3; ++i) x0[9 + i] = start.bodies[0].rot.G[i];
  const conserved c0 = of(x0, scene);
  run_errors sier2, rk;
  double sumV = 0, sumV2 = 0;
  for (auto _ : state) {
    models::md_run_options o;
    o.integrator = runs::method_named("SIER2", runs::method_system::md).splitting;
    models::with_scene_integrator<double>(scene, o, [&](const auto& method) {
      auto x = start;
      const double mvv2e = models::real_units::mvv2e<double>();
      const double t0 = thread_cpu_seconds();
      for (long k = 1; k <= sier2_steps; ++k) {
        method.step(x, h);
        // H of the rotation (the translation is force-free and left out, as in the ODE)
        const double V = x.potential, H = mvv2e * models::kinetic_energy(scene.moments, x.bodies[0].rot.G) + V;
        sumV += V, sumV2 += V * V;
        sier2.energy = std::max(sier2.energy, std::abs(H - c0.H));
        sier2.lz = std::max(sier2.lz, std::abs(models::lab_spin(x.bodies[0])[2] - c0.Lz));
      }
      sier2.cpu = thread_cpu_seconds() - t0;
      sier2.steps = sier2_steps;
      return 0;
    });
    // RKF78: its cost per step measured first, then the step that spends SIER2's CPU time on the same span
    boost::numeric::odeint::runge_kutta_fehlberg78<ode_state> stepper;
    const dipole_rhs rhs{scene.moments, &scene};
    ode_state x = x0;
    const double t1 = thread_cpu_seconds();
    for (int k = 0; k < 20000; ++k) stepper.do_step(rhs, x, 0.0, 1.0);
    const double per_step = (thread_cpu_seconds() - t1) / 20000;
    rk.steps = std::max(1L, static_cast<long>(sier2.cpu / per_step));
    const double hk = h * static_cast<double>(sier2_steps) / static_cast<double>(rk.steps);
    x = x0;
    const double t2 = thread_cpu_seconds();
    for (long k = 1; k <= rk.steps; ++k) {
      stepper.do_step(rhs, x, 0.0, hk);
      const conserved c = of(x, scene);
      rk.energy = std::max(rk.energy, std::abs(c.H - c0.H));
      rk.lz = std::max(rk.lz, std::abs(c.Lz - c0.Lz));
    }
    rk.cpu = thread_cpu_seconds() - t2;
    state.counters["rkf78_h_fs"] = hk;
  }
  const double n = static_cast<double>(sier2_steps) * static_cast<double>(state.iterations());
  const double dV = std::sqrt(sumV2 / n - (sumV / n) * (sumV / n));
  state.counters["sier2_cpu_s"] = sier2.cpu;
  state.counters["rkf78_cpu_s"] = rk.cpu;
  state.counters["sier2_max_dH_over_dV"] = sier2.energy / dV;
  state.counters["rkf78_max_dH_over_dV"] = rk.energy / dV;
  state.counters["sier2_max_dLz_over_Lz"] = sier2.lz / std::abs(c0.Lz);
  state.counters["rkf78_max_dLz_over_Lz"] = rk.lz / std::abs(c0.Lz);
}

}  // namespace

BENCHMARK_CAPTURE(md_step, MRDL, "MRDL", "");
BENCHMARK_CAPTURE(md_step, MRDL_reversed, "MRDL-reversed", "");
BENCHMARK_CAPTURE(md_step, SIER2, "SIER2", "");
BENCHMARK_CAPTURE(md_step, SEJ4, "SEJ4", "");
BENCHMARK_CAPTURE(md_step, SIER4, "SIER4", "");
BENCHMARK_CAPTURE(md_step, SIER2_N2_BAC_2, "", "N2:BAC:2");
BENCHMARK_CAPTURE(md_step, SIER2_P1_BAC_5, "", "P1:BAC:5");
BENCHMARK_CAPTURE(md_step, SIER2_R_ABC_4, "", "R:ABC:4");
BENCHMARK_CAPTURE(md_step, SIER2_RS4_S5_McLachlan, "SIER2/RS4-S5-McLachlan:CBA", "");
BENCHMARK_CAPTURE(md_step, SIER2_Yoshida, "SIER2/ABCBA4-SS3-Yoshida", "");
BENCHMARK(odeint_at_equal_cpu)->Iterations(1)->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
