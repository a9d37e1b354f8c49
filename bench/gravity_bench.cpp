// The mutual gravity's cost per evaluation (U, the force, both torques) by order: the written-out path
// at orders 2 and 4, the series at every order 2…10, for Didymos and Dimorphos as ellipsoids (turned
// arbitrarily, 1.2 km apart; their odd degrees vanish and are skipped) and as bodies with every integral
// present (a shape model's case: the ellipsoids' integrals plus 1 % of noise in every monomial). The
// issue's goal: order 8 at most 5× order 4.
#include <benchmark/benchmark.h>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/monomial_moments.hpp"
#include "rotlie/models/scenes/mutual_gravity.hpp"

namespace {

using namespace rotlie::models;

struct didymos_pair {
  gravitating_body<double> primary, secondary;
  mat3<double> Q1, Q2;
  vec3<double> r{0.7, 0.9, 0.3};
  explicit didymos_pair(int degree)
      : primary(ellipsoid_body(5.2e11, 0.39888, 0.39130, 0.38348, degree)),
        secondary(ellipsoid_body(4.9e9, 0.10316, 0.07935, 0.06613, degree)),
        Q1(rotation<double>({0.36, 0.48, 0.8}, 0.9)),
        Q2(rotation<double>({0.6, 0.0, -0.8}, 2.1)) {}
};

// every monomial moment perturbed: the cost of a body whose integrals are all nonzero
gravitating_body<double> dense(gravitating_body<double> body) {
  double x = 0.37;
  for (std::size_t i = 1; i < body.moments.size(); ++i) {
    x = 4 * x * (1 - x);  // a logistic sequence: deterministic, all nonzero
    body.moments[i] += 0.01 * (x - 0.5) * std::abs(body.moments[i == 1 ? 0 : i]) + 1e-3 * body.moments[0] * (x - 0.5) * (i < 4 ? 0.0 : 1e-3);
  }
  for (int i = 1; i < 4; ++i) body.moments[static_cast<std::size_t>(i)] = 0;  // about the centre of mass
  return body;
}

void written_out(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const didymos_pair p(4);
  for (auto _ : state) benchmark::DoNotOptimize(mutual_gravity_written_out(p.primary, p.Q1, p.secondary, p.Q2, p.r, 6.6743e-20, order));
}

void series(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const didymos_pair p(std::max(order, 4));
  mutual_gravity<double> g;
  for (auto _ : state) {
    mutual_gravity_series(p.primary, p.Q1, p.secondary, p.Q2, p.r, 6.6743e-20, order, true, g.U, g.F, g.M1, g.M2);
    benchmark::DoNotOptimize(g);
  }
}

void series_dense(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  didymos_pair p(std::max(order, 5));
  p.primary = dense(p.primary), p.secondary = dense(p.secondary);
  mutual_gravity<double> g;
  for (auto _ : state) {
    mutual_gravity_series(p.primary, p.Q1, p.secondary, p.Q2, p.r, 6.6743e-20, order, true, g.U, g.F, g.M1, g.M2);
    benchmark::DoNotOptimize(g);
  }
}

}  // namespace

BENCHMARK(written_out)->Arg(2)->Arg(4);
BENCHMARK(series)->DenseRange(2, 10);
BENCHMARK(series_dense)->DenseRange(2, 10);
BENCHMARK_MAIN();
