// The numeric core's unit costs in double: one rotation about a principal axis (a stage), one
// rotation about G, a whole step of the water schemes, and one evaluation of the exact flow.
#include <benchmark/benchmark.h>

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace {

using namespace rotlie;
const models::vec3<double> water{10220.0 / 29376, 19187.0 / 29376, 1};

models::body_state<double> start() {
  models::body_state<double> s;
  s.G = {1, 1, 1};
  return s;
}

void rotation_about_principal_axis(benchmark::State& state) {
  auto s = start();
  int k = 0;
  for (auto _ : state) {
    models::rotate_about_axis(s, k, 1 / water[static_cast<std::size_t>(k)], 1e-3);
    k = k == 2 ? 0 : k + 1;
    benchmark::DoNotOptimize(s);
  }
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

void exact_flow_evaluation(benchmark::State& state) {
  const models::exact_free_body<double> exact(water, start());
  double t = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(exact.at(t));
    t += 0.37;
  }
}

void exact_flow_construction(benchmark::State& state) {
  const auto s = start();
  for (auto _ : state) benchmark::DoNotOptimize(models::exact_free_body<double>(water, s));
}

}  // namespace

BENCHMARK(rotation_about_principal_axis);
BENCHMARK(rotation_about_momentum);
BENCHMARK_CAPTURE(scheme_step, ABCBA2, "ABCBA2:ABC");
BENCHMARK_CAPTURE(scheme_step, ABCBA4_SS3_Yoshida, "ABCBA4-SS3-Yoshida:ACB");
BENCHMARK_CAPTURE(scheme_step, RSR4_SS3_Yoshida, "RSR4-SS3-Yoshida:ABC");
BENCHMARK_CAPTURE(scheme_step, RS4_S5_McLachlan, "RS4-S5-McLachlan:CBA");
BENCHMARK(exact_flow_evaluation);
BENCHMARK(exact_flow_construction);
BENCHMARK_MAIN();
