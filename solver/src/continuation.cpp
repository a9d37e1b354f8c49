#include "rotlie/solver/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rotlie::solver {
namespace {

using vec3 = std::array<long double, 3>;
constexpr int max_power = 32;
using mat3 = std::array<vec3, 3>;

struct jet {
  long double value = 0;
  vec3 gradient{};
  mat3 hessian{};
};

// Value, gradient and (when asked) Hessian of a polynomial in up to three unknowns.
jet evaluate_jet(const numeric_polynomial& p, const point3& x, bool hessian) {
  const int d = p.max_degree;
  if (d >= max_power) throw std::invalid_argument("a condition of degree above 31 in one coefficient");
  std::array<std::array<long double, max_power>, 3> power;  // no allocation: this is the inner loop
  for (int k = 0; k < 3; ++k) {
    power[k][0] = 1.0L;
    for (int e = 1; e <= d; ++e) power[k][e] = power[k][e - 1] * x[k];
  }
  // x^e, its first and second derivative factors (e x^(e−1), e(e−1) x^(e−2))
  const auto pw = [&](int k, int e) { return power[k][e]; };
  const auto d1 = [&](int k, int e) { return e >= 1 ? e * power[k][e - 1] : 0.0L; };
  const auto d2 = [&](int k, int e) { return e >= 2 ? e * (e - 1) * power[k][e - 2] : 0.0L; };
  jet out;
  for (const auto& t : p.terms) {
    const auto& e = t.x;
    const long double m0 = pw(0, e[0]), m1 = pw(1, e[1]), m2 = pw(2, e[2]);
    const long double f0 = d1(0, e[0]), f1 = d1(1, e[1]), f2 = d1(2, e[2]);
    out.value += t.c * m0 * m1 * m2;
    out.gradient[0] += t.c * f0 * m1 * m2;
    out.gradient[1] += t.c * m0 * f1 * m2;
    out.gradient[2] += t.c * m0 * m1 * f2;
    if (!hessian) continue;
    out.hessian[0][0] += t.c * d2(0, e[0]) * m1 * m2;
    out.hessian[1][1] += t.c * m0 * d2(1, e[1]) * m2;
    out.hessian[2][2] += t.c * m0 * m1 * d2(2, e[2]);
    out.hessian[0][1] += t.c * f0 * f1 * m2;
    out.hessian[0][2] += t.c * f0 * m1 * f2;
    out.hessian[1][2] += t.c * m0 * f1 * f2;
  }
  out.hessian[1][0] = out.hessian[0][1];
  out.hessian[2][0] = out.hessian[0][2];
  out.hessian[2][1] = out.hessian[1][2];
  return out;
}

// The jets of every polynomial of a stacked set at x (out[j] for polynomial j): the powers and
// derivative factors of each monomial are formed once and shared by all the polynomials.
constexpr std::size_t max_stacked = 24;
void evaluate_stacked(const stacked_polynomials& p, const point3& x, bool hessian, std::array<jet, max_stacked>& out) {
  const int d = p.max_degree;
  if (d >= max_power) throw std::invalid_argument("a condition of degree above 31 in one coefficient");
  if (p.count > max_stacked) throw std::invalid_argument("more polynomials in one system than the stacked evaluation holds");
  std::array<std::array<long double, max_power>, 3> power;  // no allocation: this is the inner loop
  for (int k = 0; k < 3; ++k) {
    power[k][0] = 1.0L;
    for (int e = 1; e <= d; ++e) power[k][e] = power[k][e - 1] * x[k];
  }
  for (std::size_t j = 0; j < p.count; ++j) out[j] = jet{};
  const long double* c = p.c.data();
  for (const auto& e : p.monomials) {
    const long double m0 = power[0][e[0]], m1 = power[1][e[1]], m2 = power[2][e[2]];
    const long double f0 = e[0] >= 1 ? e[0] * power[0][e[0] - 1] : 0.0L;
    const long double f1 = e[1] >= 1 ? e[1] * power[1][e[1] - 1] : 0.0L;
    const long double f2 = e[2] >= 1 ? e[2] * power[2][e[2] - 1] : 0.0L;
    const long double v = m0 * m1 * m2, g0 = f0 * m1 * m2, g1 = m0 * f1 * m2, g2 = m0 * m1 * f2;
    long double h00 = 0, h11 = 0, h22 = 0, h01 = 0, h02 = 0, h12 = 0;
    if (hessian) {
      h00 = (e[0] >= 2 ? e[0] * (e[0] - 1) * power[0][e[0] - 2] : 0.0L) * m1 * m2;
      h11 = m0 * (e[1] >= 2 ? e[1] * (e[1] - 1) * power[1][e[1] - 2] : 0.0L) * m2;
      h22 = m0 * m1 * (e[2] >= 2 ? e[2] * (e[2] - 1) * power[2][e[2] - 2] : 0.0L);
      h01 = f0 * f1 * m2;
      h02 = f0 * m1 * f2;
      h12 = m0 * f1 * f2;
    }
    for (std::size_t j = 0; j < p.count; ++j, ++c) {
      const long double k = *c;
      if (k == 0) continue;
      jet& o = out[j];
      o.value += k * v;
      o.gradient[0] += k * g0;
      o.gradient[1] += k * g1;
      o.gradient[2] += k * g2;
      if (!hessian) continue;
      o.hessian[0][0] += k * h00;
      o.hessian[1][1] += k * h11;
      o.hessian[2][2] += k * h22;
      o.hessian[0][1] += k * h01;
      o.hessian[0][2] += k * h02;
      o.hessian[1][2] += k * h12;
    }
  }
  for (std::size_t j = 0; j < p.count; ++j) {
    out[j].hessian[1][0] = out[j].hessian[0][1];
    out[j].hessian[2][0] = out[j].hessian[0][2];
    out[j].hessian[2][1] = out[j].hessian[1][2];
  }
}

long double det3(const vec3& a, const vec3& b, const vec3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The Lagrange system P1 = P2 = det[∇f; ∇P1; ∇P2] = 0 and its Jacobian from the jets of P1, P2 and
// of the terms q of H_R5: f = ‖H_R5‖² = Σ q², ∇f = 2 Σ q ∇q, Hf = 2 Σ (∇q ∇qᵀ + q Hq).
void lagrange_at(const jet& g1, const jet& g2, const jet* q, std::size_t terms, vec3& F, mat3& J) {
  F = {g1.value, g2.value, 0};
  J = {g1.gradient, g2.gradient, vec3{}};
  vec3 gf{};
  mat3 hf{};
  for (std::size_t m = 0; m < terms; ++m) {
    const jet& j = q[m];
    for (int a = 0; a < 3; ++a) {
      gf[a] += 2 * j.value * j.gradient[a];
      for (int b = 0; b < 3; ++b) hf[a][b] += 2 * (j.gradient[a] * j.gradient[b] + j.value * j.hessian[a][b]);
    }
  }
  F[2] = det3(gf, g1.gradient, g2.gradient);
  for (int k = 0; k < 3; ++k)  // ∂_k det: one row differentiated at a time (Hessians are symmetric)
    J[2][k] = det3(hf[k], g1.gradient, g2.gradient) + det3(gf, g1.hessian[k], g2.gradient) +
              det3(gf, g1.gradient, g2.hessian[k]);
}

// The residual F(x) and Jacobian J(x) of the square system (2 × 2 for N, 3 × 3 for R and P).
void system_at(const numeric_system& s, const point3& x, vec3& F, mat3& J) {
  if (s.unknowns == 3) {  // P1, P2 and H_R5's terms, stacked by evaluate_system
    if (s.stacked.count < 2) throw std::invalid_argument("a Lagrange system without its stacked polynomials");
    std::array<jet, max_stacked> j;  // no allocation: this is the inner loop
    evaluate_stacked(s.stacked, x, true, j);
    lagrange_at(j[0], j[1], j.data() + 2, s.stacked.count - 2, F, J);
    return;
  }
  const jet g1 = evaluate_jet(s.p1, x, false), g2 = evaluate_jet(s.p2, x, false);
  F = {g1.value, g2.value, 0};
  J = {g1.gradient, g2.gradient, {0, 0, 1}};
}

// J⁻¹ F by Gauss–Jordan with partial pivoting on the row-equilibrated system, and the reciprocal
// condition number of that system (infinity norm); false when J is singular.
bool solve_linear(mat3 J, vec3 F, int dims, vec3& step, long double& rcond) {
  for (int r = 0; r < dims; ++r) {  // each equation scaled to unit size: the test is scale-free
    long double m = 0;
    for (int c = 0; c < dims; ++c) m = std::max(m, std::fabs(J[r][c]));
    if (m == 0) return false;
    for (int c = 0; c < dims; ++c) J[r][c] /= m;
    F[r] /= m;
  }
  long double norm = 0;
  for (int r = 0; r < dims; ++r) {
    long double s = 0;
    for (int c = 0; c < dims; ++c) s += std::fabs(J[r][c]);
    norm = std::max(norm, s);
  }
  mat3 inv{};
  for (int r = 0; r < dims; ++r) inv[r][r] = 1;
  for (int c = 0; c < dims; ++c) {
    int p = c;
    for (int r = c + 1; r < dims; ++r)
      if (std::fabs(J[r][c]) > std::fabs(J[p][c])) p = r;
    if (J[p][c] == 0) return false;
    std::swap(J[p], J[c]);
    std::swap(inv[p], inv[c]);
    const long double pivot = J[c][c];
    for (int k = 0; k < dims; ++k) {
      J[c][k] /= pivot;
      inv[c][k] /= pivot;
    }
    for (int r = 0; r < dims; ++r) {
      if (r == c) continue;
      const long double f = J[r][c];
      for (int k = 0; k < dims; ++k) {
        J[r][k] -= f * J[c][k];
        inv[r][k] -= f * inv[c][k];
      }
    }
  }
  long double inv_norm = 0;
  for (int r = 0; r < dims; ++r) {
    long double s = 0, v = 0;
    for (int c = 0; c < dims; ++c) {
      s += std::fabs(inv[r][c]);
      v += inv[r][c] * F[c];
    }
    inv_norm = std::max(inv_norm, s);
    step[r] = v;
  }
  rcond = 1 / (norm * inv_norm);
  return std::isfinite(rcond);
}

long double distance(const point3& a, const point3& b) {
  return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
}
long double size(const point3& a) { return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])}); }

}  // namespace

newton_result newton_solve(const numeric_system& system, const point3& start, const newton_limits& limits) {
  newton_result r;
  r.x = start;
  const int dims = system.unknowns;
  for (r.iterations = 1; r.iterations <= limits.max_iterations; ++r.iterations) {
    vec3 F, step{};
    mat3 J;
    system_at(system, r.x, F, J);
    if (!solve_linear(J, F, dims, step, r.condition)) return r;
    long double change = 0;
    for (int k = 0; k < dims; ++k) {
      r.x[k] -= step[k];
      change = std::max(change, std::fabs(step[k]));
    }
    if (!std::isfinite(change)) return r;
    if (change <= limits.step_tolerance * (1 + size(r.x))) {
      r.converged = r.condition >= limits.min_condition;
      return r;
    }
  }
  return r;
}

namespace {

// Start i moved by Newton, within the limits: its travel bounded by its distance to the other starts.
std::optional<point3> continue_one(const numeric_system& system, const std::vector<point3>& starts, std::size_t i,
                                   const std::vector<point3>& predicted, const newton_limits& limits) {
  long double nearest = 4 * (1 + size(starts[i]));
  for (std::size_t j = 0; j < starts.size(); ++j)
    if (j != i) nearest = std::min(nearest, distance(starts[i], starts[j]));
  const point3& guess = predicted.empty() ? starts[i] : predicted[i];
  const auto r = newton_solve(system, guess, limits);
  if (!r.converged || distance(r.x, guess) > limits.max_travel * nearest) return std::nullopt;
  return r.x;
}

}  // namespace

std::vector<std::optional<point3>> continue_each(const numeric_system& system, const std::vector<point3>& starts,
                                                 const newton_limits& limits) {
  std::vector<std::optional<point3>> out;
  for (std::size_t i = 0; i < starts.size(); ++i) out.push_back(continue_one(system, starts, i, {}, limits));
  return out;
}

std::optional<std::vector<point3>> continue_solutions(const numeric_system& system, const std::vector<point3>& starts,
                                                      const std::vector<point3>& predicted, const newton_limits& limits) {
  std::vector<point3> out;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const auto x = continue_one(system, starts, i, predicted, limits);
    if (!x) return std::nullopt;
    out.push_back(*x);
  }
  for (std::size_t i = 0; i + 1 < out.size(); ++i)
    for (std::size_t j = i + 1; j < out.size(); ++j)
      if (distance(out[i], out[j]) <= 1e-8L * (1 + size(out[i]))) return std::nullopt;
  return out;
}

long double remainder_norm(const numeric_system& system, const point3& x) {
  long double s = 0;
  for (const auto& q : system.h5) {
    const long double v = evaluate_jet(q, x, false).value;
    s += v * v;
  }
  return std::sqrt(s);
}

}  // namespace rotlie::solver
