// Symbolic modified Hamiltonians: all order-5 remainders of N1–N7, R, P1–P15, RSRSRSR and
// SRSRSRS, symbolic in the stage coefficients and the inverse moments; and the BCH series by degree.
// Each run checks Theorem 1 support and the reduction formula (63) of H_R5.
#include <benchmark/benchmark.h>

#include "rotlie/bch/lie_series.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/theorems.hpp"

namespace {

using namespace rotlie;

bool h5_has_paper_structure(const bch::symbolic_polynomial& h5) {
  for (const auto& [m, c] : h5.terms())
    if (!lie::theorem1_allows(5, m)) return false;
  return bch::theorem2_pairing(h5).is_zero();
}

void all_order5_remainders(benchmark::State& state) {
  const auto w = bch::inverse_inertia::symbolic();
  for (auto _ : state) {
    for (const auto& s : bch::named_schemes()) {
      const auto layout = bch::layout_scheme(s.word, s.split);
      const auto c = bch::make_coefficients(layout);
      const auto k = bch::compute_modified_hamiltonian(bch::stage_elements(layout, c, w), 5);
      if (!h5_has_paper_structure(k.remainder[5])) state.SkipWithError("H_R5 violates (62)-(63)");
      benchmark::DoNotOptimize(k.remainder.data());
    }
  }
  state.counters["schemes"] = static_cast<double>(bch::named_schemes().size());
}

void bch_series_by_degree(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(bch::bch_series(degree).coefficients.size());
}

void symmetric_bch_series_by_degree(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(bch::symmetric_bch_series(degree).coefficients.size());
}

}  // namespace

BENCHMARK(all_order5_remainders)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(bch_series_by_degree)->DenseRange(6, 14, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(symmetric_bch_series_by_degree)->DenseRange(5, 11, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
