#pragma once
// A cheap predictor of the numeric protocol's error (LV section 4.1) from the scheme's remainder
// alone, without running the scheme. A symmetric 4th-order composition is, up to O(h^6), the exact
// flow of hK = hH + h^5 H_R5 (eq. 12), so its attitude error is h^4 δ(t) + O(h^6) with δ the
// first-order response of the free body to the perturbation H_R5, transported along the exact
// motion (variational equations). Body frame: Ω = W G (W = diag 1/I), G' = G × Ω, Q' = Q Ω̂; with
// Q_ε = Q (1 + ε ξ̂), the response obeys
//   δG' = δG × Ω + G × δΩ,   ξ' = δΩ − Ω × ξ,   δΩ = W δG + ∇H_R5(G),
// and the R^9 distance of the attitudes is ε √2 |ξ|. The predicted mean attitude error at step h
// is h^4 · mean_t √2 |ξ(t)|. H_R5 arrives as plain data (its coefficients on the monomials
// G1^a G2^b G3^c of Theorem 1), so this side needs no symbolic algebra.
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// c · G1^e[0] G2^e[1] G3^e[2].
struct remainder_term {
  std::array<int, 3> exponent{};
  double coefficient = 0;
};

struct remainder_prediction {
  /// mean over t in (0, T] of √2 |ξ(t)|: the protocol's mean attitude error divided by h^4
  double transported = 0;
  /// the simpler measure: mean over the unperturbed motion of |∇H_R5(G)| (the angular-velocity
  /// error, which drives the attitude drift) — no transport
  double mean_gradient = 0;
};

namespace detail {

inline vec3<double> cross3(const vec3<double>& a, const vec3<double>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double int_power(double x, int e) {
  double r = 1;
  for (int k = 0; k < e; ++k) r *= x;
  return r;
}

inline vec3<double> remainder_gradient(const std::vector<remainder_term>& h5, const vec3<double>& G) {
  vec3<double> g{0, 0, 0};
  for (const auto& t : h5)
    for (int i = 0; i < 3; ++i) {
      const int e = t.exponent[static_cast<std::size_t>(i)];
      if (e == 0) continue;
      double v = t.coefficient * e;
      for (int j = 0; j < 3; ++j)
        v *= int_power(G[static_cast<std::size_t>(j)], t.exponent[static_cast<std::size_t>(j)] - (j == i ? 1 : 0));
      g[static_cast<std::size_t>(i)] += v;
    }
  return g;
}

// y = (G, δG, ξ)
using response_state = std::array<vec3<double>, 3>;

inline response_state response_rate(const vec3<double>& w, const std::vector<remainder_term>& h5,
                                     const response_state& y) {
  const auto& [G, dG, xi] = y;
  const vec3<double> omega{w[0] * G[0], w[1] * G[1], w[2] * G[2]};
  const auto grad = remainder_gradient(h5, G);
  const vec3<double> d_omega{w[0] * dG[0] + grad[0], w[1] * dG[1] + grad[1], w[2] * dG[2] + grad[2]};
  const auto a = cross3(dG, omega), b = cross3(G, d_omega), c = cross3(omega, xi);
  return {cross3(G, omega), vec3<double>{a[0] + b[0], a[1] + b[1], a[2] + b[2]},
          vec3<double>{d_omega[0] - c[0], d_omega[1] - c[1], d_omega[2] - c[2]}};
}

}  // namespace detail

/// The prediction for a body I (the same unit as the remainder's), initial momentum G0, over
/// [0, T], by classical RK4 with `steps` steps (the response is smooth: 4096 steps over the
/// protocol's T = 1 are accurate to far better than the predictor's purpose).
inline remainder_prediction predict_remainder_error(const vec3<double>& I, const vec3<double>& G0, double T,
                                                    const std::vector<remainder_term>& h5, int steps = 4096) {
  if (!(T > 0) || steps < 1) throw std::invalid_argument("the predictor needs T > 0 and at least one step");
  const vec3<double> w{1 / I[0], 1 / I[1], 1 / I[2]};
  detail::response_state y{G0, vec3<double>{0, 0, 0}, vec3<double>{0, 0, 0}};
  const double h = T / steps;
  auto axpy = [](const detail::response_state& y0, double a, const detail::response_state& k) {
    detail::response_state r = y0;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) r[i][j] += a * k[i][j];
    return r;
  };
  auto norm = [](const vec3<double>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  remainder_prediction p;
  for (int n = 0; n < steps; ++n) {
    const auto k1 = detail::response_rate(w, h5, y);
    const auto k2 = detail::response_rate(w, h5, axpy(y, h / 2, k1));
    const auto k3 = detail::response_rate(w, h5, axpy(y, h / 2, k2));
    const auto k4 = detail::response_rate(w, h5, axpy(y, h, k3));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) y[i][j] += h / 6 * (k1[i][j] + 2 * k2[i][j] + 2 * k3[i][j] + k4[i][j]);
    p.transported += std::sqrt(2.0) * norm(y[2]);
    p.mean_gradient += norm(detail::remainder_gradient(h5, y[0]));
  }
  p.transported /= steps;
  p.mean_gradient /= steps;
  return p;
}

}  // namespace rotlie::models
