#pragma once
// Random rigid bodies and states for the tests of the exact free flow (the step and its batch):
// water, generic, near-spherical, thin, flat near-symmetric and near-symmetric bodies, |G| over 40
// decades, |ω| t log-uniform over [1e-6, 2] rad of either sign; and the error measure of the
// estimates (max abs entry of Q and of G/|G|).
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "model_support.hpp"
#include "random_seed.hpp"
#include "rotlie/models/rigid_body.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::test {

inline double norm(const models::vec3<double>& g) { return std::hypot(g[0], g[1], g[2]); }

// max abs entry of Q and of G/|G|, the measure of the estimates
template <class A, class B>
double entry_error(const models::body_state<A>& a, const models::body_state<B>& b, double g_scale) {
  double e = 0;
  auto take = [&e](const quad& d) { e = std::isnan(static_cast<double>(d)) ? HUGE_VAL : std::max(e, std::abs(static_cast<double>(d))); };
  for (std::size_t i = 0; i < 9; ++i) take(quad(a.Q.a[i]) - quad(b.Q.a[i]));
  for (std::size_t i = 0; i < 3; ++i) take((quad(a.G[i]) - quad(b.G[i])) / quad(g_scale));
  return e;
}

// Random bodies of the kinds the regime test covers, and a random attitude and momentum.
struct sample {
  models::vec3<double> I;
  models::body_state<double> s;
  double t;
  std::string kind;
};

class sampler {
 public:
  explicit sampler(const std::string& name) : rng_(test_seed(name)) {}

  // |ω| t log-uniform over [1e-6, 2] rad (the steps of MD and well beyond π/4), either sign
  sample next(int kind) {
    sample x;
    const double a = std::pow(10.0, -14 * U() - 1);
    switch (kind % 6) {
      case 0: x.I = water_moments<double>(), x.kind = "water"; break;
      case 1: x.I = {0.2 + 0.8 * U(), 0.2 + 0.8 * U(), 0.2 + 0.8 * U()}, x.kind = "generic"; break;
      case 2: x.I = {1, 1 + a * U(), 1 + a}, x.kind = "near-spherical"; break;
      case 3: {  // |I_3 − I_2| ≤ I_1: the triangle inequality of a thin body
        const double thin = std::pow(10.0, -8 * U() - 1);
        x.I = {thin, 1, 1 + thin * a * (2 * U() - 1)}, x.kind = "thin";
        break;
      }
      case 4: x.I = {0.5, 0.5 + a, 1}, x.kind = "flat near-symmetric"; break;
      default: x.I = {1, 1 + a, 2 + a * U()}, x.kind = "near-symmetric"; break;
    }
    const models::vec3<quad> I{quad(x.I[0]), quad(x.I[1]), quad(x.I[2])};  // the triangle inequality in float128, where the sums of these doubles are exact
    if (I[0] > I[1] + I[2] || I[1] > I[0] + I[2] || I[2] > I[0] + I[1]) return next(kind);  // no such body: draw again
    const double scale = std::pow(10.0, 40 * (U() - 0.5));
    for (std::size_t k = 0; k < 3; ++k) x.s.G[k] = scale * std::sqrt(x.I[k]) * normal_(rng_);
    x.s.Q = models::rotation<double>(unit(), 4 * U()) * models::rotation<double>(unit(), 4 * U());
    const double omega = norm(x.s.G) / std::min({x.I[0], x.I[1], x.I[2]});
    x.t = std::pow(10.0, -6 * U()) * 2 / omega * (U() < 0.5 ? -1 : 1);
    return x;
  }

 private:
  double U() { return uniform_(rng_); }
  models::vec3<double> unit() {
    const models::vec3<double> v{normal_(rng_), normal_(rng_), normal_(rng_)};
    const double n = norm(v);
    return {v[0] / n, v[1] / n, v[2] / n};
  }
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0, 1};
  std::normal_distribution<double> normal_{0, 1};
};

}  // namespace rotlie::test
