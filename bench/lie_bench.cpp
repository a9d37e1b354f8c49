// Time to compute the graded algebra L_1 … L_K (dimensions certified, Theorems 1–2 checked),
// by the certificate and by exact elimination. Each run checks that the bound is attained.
#include <benchmark/benchmark.h>

#include "rotlie/lie/lie_poisson_algebra.hpp"

namespace {

void run(benchmark::State& state, bool exact_only) {
  const int K = static_cast<int>(state.range(0));
  rotlie::lie::algebra_options options;
  options.exact_only = exact_only;
  for (auto _ : state) {
    const auto pieces = rotlie::lie::lie_poisson_algebra(K, options);
    for (const auto& p : pieces)
      if (!p.bound_attained() || !p.theorem1) state.SkipWithError("unexpected dimension or Theorem 1 failure");
    benchmark::DoNotOptimize(pieces.data());
  }
}

void algebra_certificate(benchmark::State& state) { run(state, false); }
void algebra_exact_elimination(benchmark::State& state) { run(state, true); }

}  // namespace

BENCHMARK(algebra_certificate)->Arg(10)->Arg(20)->Arg(40)->Arg(60)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(algebra_exact_elimination)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
