// Symbolic modified Hamiltonians: all order-5 remainders of N1–N7, R, P1–P15, RSRSRSR and
// SRSRSRS, symbolic in the stage coefficients and the inverse moments; and the free-algebra BCH series
// (XY, SYM to degree 20, XYZ to 14) by degree.
// Each run checks Theorem 1 support and the reduction formula (63) of H_R5.
#include <benchmark/benchmark.h>

#include "rotlie/bch/free_bch.hpp"
#include "rotlie/bch/lie_series.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/stage_hamiltonian.hpp"
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

// The free-algebra engine (exact, Lyndon basis): range(0) = degree, range(1) = threads.
template <bch::free_series S>
void free_series_by_degree(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  const bch::series_options options{static_cast<int>(state.range(1)), false};
  for (auto _ : state) benchmark::DoNotOptimize(bch::compute_free_series(S, degree, options).numerator.data());
  state.counters["terms"] = static_cast<double>(bch::lyndon_basis(bch::series_letters(S), degree).size());
}

// H_R7 of a 21-stage ABC palindrome (8 free coefficients), exact, at water: the issue's ≤ 1 s target (CPU).
void stage_hamiltonian_21_stages(benchmark::State& state) {
  const auto layout = bch::layout_scheme("ABCBABCBABCBABCBABCBA", bch::splitting::abc);
  const std::array<cln::cl_RA, 3> w{cln::cl_RA(7344) / 2555, cln::cl_RA(29376) / 19187, cln::cl_RA(1)};
  const int order = static_cast<int>(state.range(0));
  std::size_t terms = 0;
  for (auto _ : state) {
    const auto k = bch::compute_stage_hamiltonian(layout, w, order);
    terms = 0;
    for (const auto& [m, c] : k.remainder[static_cast<std::size_t>(order)].terms()) terms += c.size();
  }
  state.counters["terms"] = static_cast<double>(terms);
}

}  // namespace

BENCHMARK(stage_hamiltonian_21_stages)->Arg(5)->Arg(7)->Unit(benchmark::kMillisecond);
BENCHMARK(all_order5_remainders)->Unit(benchmark::kSecond)->Iterations(1);
// CPU time is the figure to read on a shared machine (wall time includes waiting for a core).
BENCHMARK(free_series_by_degree<bch::free_series::xy>)->ArgsProduct({benchmark::CreateDenseRange(10, 20, 1), {1}})->Unit(benchmark::kMillisecond);
BENCHMARK(free_series_by_degree<bch::free_series::sym>)->ArgsProduct({benchmark::CreateDenseRange(10, 20, 1), {1}})->Unit(benchmark::kMillisecond);
// Wall time for one and two threads side by side (the two-core target is a wall time; read it on a quiet machine).
BENCHMARK(free_series_by_degree<bch::free_series::xy>)->Args({20, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(free_series_by_degree<bch::free_series::xy>)->Args({20, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(free_series_by_degree<bch::free_series::xyz>)->Args({14, 1})->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
