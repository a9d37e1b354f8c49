// All real solutions of the N family (7 schemes × 6 permutations = 42 systems) for water,
// with the split between order conditions, elimination + root refinement, and remainders.
// Each run checks the paper's count of 90 real solutions.
#include <benchmark/benchmark.h>

#include "rotlie/solver/dedicated_schemes.hpp"

namespace {

void n_family_water(benchmark::State& state) {
  const auto body = rotlie::lie::parse_moments("water");
  const std::vector<std::string> schemes = {"N1", "N2", "N3", "N4", "N5", "N6", "N7"};
  double conditions = 0, elimination = 0, remainder = 0;
  for (auto _ : state) {
    const auto r = rotlie::solver::solve_dedicated(body, schemes, rotlie::bch::permutation_names(),
                                                   static_cast<int>(state.range(0)));
    if (r.solutions.size() != 90) state.SkipWithError("expected 90 real solutions");
    conditions += r.seconds_conditions;
    elimination += r.seconds_elimination;
    remainder += r.seconds_remainder;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["conditions_s"] = conditions / n;
  state.counters["elimination_roots_s"] = elimination / n;
  state.counters["remainder_s"] = remainder / n;
}

}  // namespace

BENCHMARK(n_family_water)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_MAIN();
