// All real solutions for water: the N family (7 schemes × 6 permutations = 42 systems, the paper's
// 90 solutions), the R family (6 systems, the paper's 46) and the P family (15 × 6 = 90 systems),
// each with the time split between order conditions, elimination (resultants), roots (isolation,
// refinement, pairing, back-substitution) and analytic remainders.
#include <benchmark/benchmark.h>

#include "rotlie/solver/dedicated_schemes.hpp"

namespace {

std::vector<std::string> family(const std::string& name, int members) {
  std::vector<std::string> out;
  if (members == 0) return {name};
  for (int i = 1; i <= members; ++i) out.push_back(name + std::to_string(i));
  return out;
}

void solve_family(benchmark::State& state, const std::vector<std::string>& schemes, std::size_t expected) {
  const auto body = rotlie::lie::parse_moments("water");
  double conditions = 0, elimination = 0, roots = 0, remainder = 0;
  for (auto _ : state) {
    const auto r = rotlie::solver::solve_dedicated(body, schemes, rotlie::bch::permutation_names(),
                                                   static_cast<int>(state.range(0)));
    if (expected != 0 && r.solutions.size() != expected) state.SkipWithError("unexpected number of real solutions");
    conditions += r.seconds_conditions;
    elimination += r.seconds_elimination;
    roots += r.seconds_roots;
    remainder += r.seconds_remainder;
    state.counters["solutions"] = static_cast<double>(r.solutions.size());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["conditions_s"] = conditions / n;
  state.counters["elimination_s"] = elimination / n;
  state.counters["roots_s"] = roots / n;
  state.counters["remainder_s"] = remainder / n;
}

void n_family_water(benchmark::State& state) { solve_family(state, family("N", 7), 90); }
void r_family_water(benchmark::State& state) { solve_family(state, family("R", 0), 46); }
void p_family_water(benchmark::State& state) { solve_family(state, family("P", 15), 0); }

}  // namespace

BENCHMARK(n_family_water)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(r_family_water)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(p_family_water)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
