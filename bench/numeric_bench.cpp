// The numeric core's unit costs in double: one rotation about a principal axis (a stage), one
// rotation about G, a whole step of the water schemes, the exact flow (construction and
// evaluation, ordinary and near the separatrix; its parts one by one; exact_free_rotation::advance
// against an exact_free_body per step, in stages of this run), and the exact flow's special functions from
// Boost.Math, GSL and models/complementary_elliptic.hpp, with their accuracy against float128
// printed before the timings.
#include <benchmark/benchmark.h>

#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <ctime>
#include <cstdio>
#include <random>
#include <vector>

#ifdef ROTLIE_BENCH_GSL
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>
#endif

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"
#include "rotlie/schemes/quad.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace {

using namespace rotlie;
const models::vec3<double> water{10220.0 / 29376, 19187.0 / 29376, 1};

models::body_state<double> start(double d = -1) {
  models::body_state<double> s;
  s.G = d < 0 ? models::vec3<double>{1, 1, 1} : models::vec3<double>{d, 1, d};
  return s;
}

// One rotation stage (rotate_about_axis), the unit of cost of this file: seconds per stage as last
// measured by rotation_about_principal_axis in this run (or by a short loop when that was filtered out).
double stage_seconds = 0;

void rotation_stages(models::body_state<double>& s, long count) {
  int k = 0;
  for (long i = 0; i < count; ++i) {
    models::rotate_about_axis(s, k, 1 / water[static_cast<std::size_t>(k)], 1e-3);
    k = k == 2 ? 0 : k + 1;
    benchmark::DoNotOptimize(s);
  }
}

// CPU time of this thread, as Google Benchmark's rates use (wall time counts other processes' load)
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double seconds_per_stage() {
  if (stage_seconds == 0) {
    auto s = start();
    constexpr long count = 4000000;
    const double t0 = thread_seconds();
    rotation_stages(s, count);
    stage_seconds = (thread_seconds() - t0) / count;
  }
  return stage_seconds;
}

// counter "stages": CPU time per iteration in rotation stages (start it just before the loop)
class stage_meter {
 public:
  stage_meter() : stage_(seconds_per_stage()), start_(thread_seconds()) {}
  double stages(const benchmark::State& state) const {
    return (thread_seconds() - start_) / static_cast<double>(state.iterations()) / stage_;
  }

 private:
  double stage_, start_;
};

void rotation_about_principal_axis(benchmark::State& state) {
  auto s = start();
  int k = 0;
  const double t0 = thread_seconds();
  for (auto _ : state) {
    models::rotate_about_axis(s, k, 1 / water[static_cast<std::size_t>(k)], 1e-3);
    k = k == 2 ? 0 : k + 1;
    benchmark::DoNotOptimize(s);
  }
  stage_seconds = (thread_seconds() - t0) / static_cast<double>(state.iterations());
  state.counters["ns_per_rotation"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void rotation_about_momentum(benchmark::State& state) {
  auto s = start();
  for (auto _ : state) {
    models::rotate_about_momentum(s, 1 / water[1], 1e-3);
    benchmark::DoNotOptimize(s);
  }
}

void scheme_step(benchmark::State& state, const char* name) {
  const models::composition_stepper<double> stepper(*schemes::reference_scheme(name), water);
  auto s = start();
  for (auto _ : state) {
    stepper.step(s, 1e-3);
    benchmark::DoNotOptimize(s);
  }
  // Time per rotation of LV's cost model (N rotations for ABC, N + 1 for RS).
  state.counters["rotations"] = stepper.cost();
  state.counters["ns_per_rotation"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * stepper.cost(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// A step of an 11-stage ABC palindrome with P1's word (LV eq. 69): the cost of P1 BAC (5) for water,
// whose coefficients (solved by the symbolic side) do not change the time of a step.
void p1_shaped_step(benchmark::State& state) {
  schemes::scheme_table t;
  t.name = "P1-shaped", t.word = "ABABACABABA", t.order = 4;
  for (const char part : t.word) t.stages.push_back({part, "", part == 'A' ? "0.16666666666666666" : part == 'B' ? "0.25" : "1"});
  const models::composition_stepper<double> stepper(t, water);
  auto s = start();
  const stage_meter meter;
  for (auto _ : state) {
    stepper.step(s, 1e-3);
    benchmark::DoNotOptimize(s);
  }
  state.counters["stages"] = meter.stages(state);
}

// d < 0: G = (1, 1, 1); otherwise G = (d, 1, d), d off the middle axis (m_c ≈ 2d²)
void exact_flow_evaluation(benchmark::State& state, double d) {
  const models::exact_free_body<double> exact(water, start(d));
  double t = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(exact.at(t));
    t += 0.37;
    if (t > 30) t = 0;  // stay within the double range of the estimate (no float128 redo)
  }
}

void exact_flow_construction(benchmark::State& state, double d) {
  const auto s = start(d);
  for (auto _ : state) benchmark::DoNotOptimize(models::exact_free_body<double>(water, s));
}

void exact_flow_construction_and_evaluation(benchmark::State& state, double d) {
  const auto s = start(d);
  double t = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(models::exact_free_body<double>(water, s).at(t));
    t = t > 10 ? 0.1 : t + 0.37;
  }
}

// One free flight as SIER2/SIER4 take it: the same body state advanced step after step by t (here
// |ω| t ≈ 0.1 rad, about h = 8 fs for water at 297 K), before (an exact_free_body built and evaluated
// per call) and after (exact_free_rotation::advance, the body's constants kept).
// d < 0: G = (1, 1, 1); otherwise G = (d, 1, d), near the middle axis.
void exact_free_rotation_old_path(benchmark::State& state, double d) {
  auto s = start(d);
  const double t = 0.02;
  const stage_meter meter;
  for (auto _ : state) {
    s = models::exact_free_body<double>(water, s).evaluate(t).state;
    benchmark::DoNotOptimize(s);
  }
  state.counters["stages"] = meter.stages(state);
}

void exact_free_rotation_advance(benchmark::State& state, double d) {
  auto s = start(d);
  const models::exact_free_rotation<double> rotor(water);
  const double t = 0.02;
  const stage_meter meter;
  for (auto _ : state) {
    benchmark::DoNotOptimize(rotor.advance(s, t));
    benchmark::DoNotOptimize(s);
  }
  state.counters["stages"] = meter.stages(state);
}

// Canonical momenta of water (components ~ N(0, I_k)): a new state at every call, as after a kick.
void exact_free_rotation_advance_canonical(benchmark::State& state, bool old_path) {
  std::mt19937_64 rng(12);
  std::normal_distribution<double> normal(0, 1);
  std::vector<models::body_state<double>> states(1024);
  for (auto& s : states)
    for (std::size_t k = 0; k < 3; ++k) s.G[k] = std::sqrt(water[k]) * normal(rng);
  const models::exact_free_rotation<double> rotor(water);
  const double t = 0.05;  // |ω| t ≈ 0.1 rad on average
  std::size_t i = 0;
  const stage_meter meter;
  for (auto _ : state) {
    auto& s = states[i++ & 1023];
    if (old_path)
      s = models::exact_free_body<double>(water, s).evaluate(t).state;
    else
      benchmark::DoNotOptimize(rotor.advance(s, t));
    benchmark::DoNotOptimize(s);
  }
  state.counters["stages"] = meter.stages(state);
}

// advance_all(rotors, …) of `states` over t = 0.05 per iteration; counters per body, in ns and in
// rotation stages, and the vector target as the label.
template <class Rotors>
void advance_all_timed(benchmark::State& state, const Rotors& rotors, std::vector<models::body_state<double>>& states) {
  const std::size_t n = states.size();
  const stage_meter meter;
  for (auto _ : state) {
    models::advance_all(rotors, n, [&](std::size_t i) -> models::body_state<double>& { return states[i]; }, 0.05);
    benchmark::ClobberMemory();
  }
  state.counters["stages_per_body"] = meter.stages(state) / static_cast<double>(n);
  state.counters["ns_per_body"] = benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(n),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(models::batch_target());
}

// The exact flow of N water bodies at once (advance_all: blocks of 64, vectorised across bodies,
// exact_free_rotation_batch.hpp): canonical states advanced over t = 0.05 each call (every free
// flight starts from a new state); counters per body, in ns and in rotation stages.
void exact_free_rotation_batch(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(12);
  std::normal_distribution<double> normal(0, 1);
  std::vector<models::body_state<double>> states(n);
  for (auto& s : states)
    for (std::size_t k = 0; k < 3; ++k) s.G[k] = std::sqrt(water[k]) * normal(rng);
  advance_all_timed(state, models::exact_free_rotation<double>(water), states);
}

// The same with each body's own rotor, its moments water's within 1e-13 (LAMMPS's molecules of one
// shape): the vector step reads each lane's constants from a table built per block.
void exact_free_rotation_batch_own_rotors(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(12);
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> spread(-1e-13, 1e-13);
  std::vector<models::body_state<double>> states(n);
  std::vector<models::exact_free_rotation<double>> rotors;
  rotors.reserve(n);
  std::vector<const models::exact_free_rotation<double>*> own(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) states[i].G[k] = std::sqrt(water[k]) * normal(rng);
    rotors.emplace_back(models::vec3<double>{water[0] * (1 + spread(rng)), water[1] * (1 + spread(rng)), water[2] * (1 + spread(rng))});
    own[i] = &rotors.back();
  }
  advance_all_timed(state, own.data(), states);
}

// The float128 path: what an evaluation costs when the estimate asks for it (long times).
void exact_flow_float128_evaluation(benchmark::State& state) {
  const models::exact_free_body<double> exact(water, start());
  double t = 1e6;
  for (auto _ : state) {
    benchmark::DoNotOptimize(exact.at(t));
    t += 0.37;
  }
}

// ---- the exact flow's parts, one at a time, at the water state G = (1, 1, 1) (where the time goes)
struct water_flow_point {
  double m, mc, n, K;
};
water_flow_point water_point() {
  const models::detail::free_body_motion<double> core(water, start().G, models::mat3<double>::identity());
  return {core.parameter(), core.complementary_parameter(), core.n(), core.quarter_period()};
}
void exact_part_energy_difference(benchmark::State& state) {
  auto G = start().G;
  bool inexact = false;
  for (auto _ : state) {
    benchmark::DoNotOptimize(G);
    benchmark::DoNotOptimize(models::detail::middle_energy_difference<double>(water, G, 0, 1, 2, inexact));
  }
}
void exact_part_complete_first_kind(benchmark::State& state) {
  double mc = water_point().mc;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mc);
    benchmark::DoNotOptimize(models::elliptic::complete_first_kind(mc));
  }
}
void exact_part_complete_third_kind(benchmark::State& state) {  // D(K) = n/3 R_J(0, m_c, 1, 1 − n)
  const auto p = water_point();
  double mc = p.mc;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mc);
    benchmark::DoNotOptimize(p.n / 3 * boost::math::ellint_rj(0.0, mc, 1.0, 1 - p.n, models::elliptic::policy()));
  }
}
void exact_part_initial_phase(benchmark::State& state) {  // u₀ = s R_F(c², c² + m_c s², 1)
  const auto p = water_point();
  double s = 0.6, c = 0.8;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s);
    benchmark::DoNotOptimize(s * boost::math::ellint_rf(c * c, c * c + p.mc * s * s, 1.0, models::elliptic::policy()));
  }
}
void exact_part_jacobi(benchmark::State& state, double u) {
  const auto p = water_point();
  for (auto _ : state) {
    benchmark::DoNotOptimize(u);
    benchmark::DoNotOptimize(models::elliptic::jacobi_functions(u, p.m, p.mc));
  }
}
void exact_part_third_minus_first(benchmark::State& state, double u) {  // Π − F at u: one R_J
  const auto p = water_point();
  const auto j = models::elliptic::jacobi_functions(u, p.m, p.mc);
  auto jj = j;
  for (auto _ : state) {
    benchmark::DoNotOptimize(jj);
    benchmark::DoNotOptimize(models::elliptic::third_minus_first(jj, p.n, 1 - p.n * jj.sn * jj.sn));
  }
}
void exact_part_sincos(benchmark::State& state) {
  double x = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(std::cos(x) + std::sin(x));
  }
}
void exact_part_attitude(benchmark::State& state) {  // three 3×3 products and a transpose, as in at()
  models::mat3<double> a = models::mat3<double>::identity(), b = a, c = a;
  for (auto _ : state) {
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(transpose(c * (a * b)) * a);
  }
}

// ---- special functions: m = 1 − m_c
struct parameter_point {
  double m, mc;
};
const parameter_point ordinary{0.53, 0.47}, near_one{1 - 1e-10, 1e-10};

void jacobi_complementary(benchmark::State& state, parameter_point p) {
  double u = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(models::elliptic::jacobi_functions(u, p.m, p.mc));
    u = u > 3 ? 0.1 : u + 0.013;
  }
}
void jacobi_boost(benchmark::State& state, parameter_point p) {
  double u = 0.1, cn, dn;
  const double k = std::sqrt(p.m);
  for (auto _ : state) {
    benchmark::DoNotOptimize(boost::math::jacobi_elliptic(k, u, &cn, &dn));
    u = u > 3 ? 0.1 : u + 0.013;
  }
}
void carlson_boost(benchmark::State& state, bool promote) {
  double x = 0.1;
  const models::elliptic::policy fast;
  for (auto _ : state) {
    benchmark::DoNotOptimize(promote ? boost::math::ellint_rf(x, 0.3, 1.0) + boost::math::ellint_rj(x, 0.3, 1.0, 1.4)
                                     : boost::math::ellint_rf(x, 0.3, 1.0, fast) + boost::math::ellint_rj(x, 0.3, 1.0, 1.4, fast));
    x = x > 1 ? 0.1 : x + 0.013;
  }
}
#ifdef ROTLIE_BENCH_GSL
void jacobi_gsl(benchmark::State& state, parameter_point p) {
  double u = 0.1, sn, cn, dn;
  for (auto _ : state) {
    gsl_sf_elljac_e(u, p.m, &sn, &cn, &dn);
    benchmark::DoNotOptimize(sn + cn + dn);
    u = u > 3 ? 0.1 : u + 0.013;
  }
}
void carlson_gsl(benchmark::State& state) {
  double x = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(gsl_sf_ellint_RF(x, 0.3, 1.0, GSL_PREC_DOUBLE) + gsl_sf_ellint_RJ(x, 0.3, 1.0, 1.4, GSL_PREC_DOUBLE));
    x = x > 1 ? 0.1 : x + 0.013;
  }
}
#endif

double gap(double x, const quad& y) { return std::abs(static_cast<double>(quad(x) - y)); }

// Max abs error of sn, cn, dn over u ∈ [0, K] and of R_F, R_J on a grid, against float128.
void print_accuracy() {
  std::printf("max abs error against float128 (u in [0, K], 400 points)\n");
  for (const auto& p : {ordinary, near_one}) {
    const quad mq = 1 - quad(p.mc), mcq = p.mc;
    const double K = models::elliptic::complete_first_kind(p.mc);
    double ours = 0, boost_err = 0, gsl_err = 0;
    for (int i = 0; i <= 400; ++i) {
      const double u = K * i / 400;
      const auto r = models::elliptic::jacobi_functions(quad(u), mq, mcq);
      const auto o = models::elliptic::jacobi_functions(u, p.m, p.mc);
      ours = std::max({ours, gap(o.sn, r.sn), gap(o.cn, r.cn), gap(o.dn, r.dn)});
      double cn, dn;
      const double sn = boost::math::jacobi_elliptic(std::sqrt(p.m), u, &cn, &dn);
      boost_err = std::max({boost_err, gap(sn, r.sn), gap(cn, r.cn), gap(dn, r.dn)});
#ifdef ROTLIE_BENCH_GSL
      double s2, c2, d2;
      gsl_sf_elljac_e(u, p.m, &s2, &c2, &d2);
      gsl_err = std::max({gsl_err, gap(s2, r.sn), gap(c2, r.cn), gap(d2, r.dn)});
#endif
    }
    std::printf("  sn cn dn, m_c = %g: complementary %.2e, Boost jacobi_elliptic %.2e, GSL elljac %.2e\n", p.mc, ours,
                boost_err, gsl_err);
  }
  const models::elliptic::policy fast;
  double rf_b = 0, rj_b = 0, rf_g = 0, rj_g = 0;
  for (int i = 0; i <= 50; ++i)
    for (const double y : {1e-12, 1e-6, 0.3, 1.0}) {
      const double x = i / 50.0, p = 1 + i / 10.0;
      const quad rf = boost::math::ellint_rf(quad(x), quad(y), quad(1)), rj = boost::math::ellint_rj(quad(x), quad(y), quad(1), quad(p));
      rf_b = std::max(rf_b, gap(boost::math::ellint_rf(x, y, 1.0, fast), rf) / static_cast<double>(rf));
      rj_b = std::max(rj_b, gap(boost::math::ellint_rj(x, y, 1.0, p, fast), rj) / static_cast<double>(rj));
#ifdef ROTLIE_BENCH_GSL
      rf_g = std::max(rf_g, gap(gsl_sf_ellint_RF(x, y, 1.0, GSL_PREC_DOUBLE), rf) / static_cast<double>(rf));
      rj_g = std::max(rj_g, gap(gsl_sf_ellint_RJ(x, y, 1.0, p, GSL_PREC_DOUBLE), rj) / static_cast<double>(rj));
#endif
    }
  std::printf("  Carlson (Boost without promotion to long double), max relative error: R_F Boost %.2e GSL %.2e; R_J Boost %.2e GSL %.2e\n", rf_b, rf_g, rj_b, rj_g);
#ifndef ROTLIE_BENCH_GSL
  std::printf("  (GSL not found: its columns are 0)\n");
#endif
}

}  // namespace

BENCHMARK(rotation_about_principal_axis);
BENCHMARK(rotation_about_momentum);
BENCHMARK_CAPTURE(scheme_step, ABCBA2, "ABCBA2:ABC");
BENCHMARK_CAPTURE(scheme_step, ABCBA4_SS3_Yoshida, "ABCBA4-SS3-Yoshida:ACB");
BENCHMARK_CAPTURE(scheme_step, RSR4_SS3_Yoshida, "RSR4-SS3-Yoshida:ABC");
BENCHMARK_CAPTURE(scheme_step, RS4_S5_McLachlan, "RS4-S5-McLachlan:CBA");
BENCHMARK_CAPTURE(exact_flow_evaluation, water, -1.0);
BENCHMARK_CAPTURE(exact_flow_evaluation, middle_axis_1e_10, 1e-10);
BENCHMARK_CAPTURE(exact_flow_construction, water, -1.0);
BENCHMARK_CAPTURE(exact_flow_construction, middle_axis_1e_10, 1e-10);
BENCHMARK_CAPTURE(exact_flow_construction_and_evaluation, water, -1.0);
BENCHMARK_CAPTURE(exact_flow_construction_and_evaluation, middle_axis_1e_10, 1e-10);
BENCHMARK(exact_flow_float128_evaluation);
BENCHMARK_CAPTURE(exact_free_rotation_old_path, water, -1.0);
BENCHMARK_CAPTURE(exact_free_rotation_advance, water, -1.0);
BENCHMARK_CAPTURE(exact_free_rotation_old_path, middle_axis_1e_10, 1e-10);
BENCHMARK_CAPTURE(exact_free_rotation_advance, middle_axis_1e_10, 1e-10);
BENCHMARK_CAPTURE(exact_free_rotation_advance_canonical, old_path, true);
BENCHMARK_CAPTURE(exact_free_rotation_advance_canonical, advance, false);
BENCHMARK(exact_free_rotation_batch)->Arg(1)->Arg(8)->Arg(64)->Arg(4096);
BENCHMARK(exact_free_rotation_batch_own_rotors)->Arg(64)->Arg(4096);
BENCHMARK(p1_shaped_step);
BENCHMARK(exact_part_energy_difference);
BENCHMARK(exact_part_complete_first_kind);
BENCHMARK(exact_part_complete_third_kind);
BENCHMARK(exact_part_initial_phase);
BENCHMARK_CAPTURE(exact_part_jacobi, u_0_3, 0.3);
BENCHMARK_CAPTURE(exact_part_jacobi, u_1_0, 1.0);
BENCHMARK_CAPTURE(exact_part_third_minus_first, u_0_3, 0.3);
BENCHMARK_CAPTURE(exact_part_third_minus_first, u_1_0, 1.0);
BENCHMARK(exact_part_sincos);
BENCHMARK(exact_part_attitude);
BENCHMARK_CAPTURE(jacobi_complementary, ordinary, ordinary);
BENCHMARK_CAPTURE(jacobi_complementary, near_one, near_one);
BENCHMARK_CAPTURE(jacobi_boost, ordinary, ordinary);
BENCHMARK_CAPTURE(jacobi_boost, near_one, near_one);
BENCHMARK_CAPTURE(carlson_boost, long_double_inside, true);
BENCHMARK_CAPTURE(carlson_boost, double_inside, false);
#ifdef ROTLIE_BENCH_GSL
BENCHMARK_CAPTURE(jacobi_gsl, ordinary, ordinary);
BENCHMARK_CAPTURE(jacobi_gsl, near_one, near_one);
BENCHMARK(carlson_gsl);
#endif

int main(int argc, char** argv) {
  print_accuracy();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
