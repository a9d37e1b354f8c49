#pragma once
// The integrators a binary-asteroid researcher would otherwise use (those of GUBAS, Davis & Scheeres):
//   binary_rk4   the classical fixed-step Runge–Kutta method on ṙ, v̇, Q̇, Ġ (binary_system::derivative);
//                Q leaves the rotations at the size of the truncation error, nothing projects it back;
//   binary_lgvi  the Lie-group variational integrator of the full body problem (Lee, Leok & McClamroch
//                2007, CMAME 196, 2907; written from their discrete equations, inertial frame):
//                  h Ŝ(Πᵢ) + h²/2 Ŝ(Mᵢ) = Fᵢ J_dᵢ − J_dᵢ Fᵢᵀ      (Fᵢ ∈ SO(3) the body's turn over the step)
//                  r' = r + h v + h²/(2μ) F,   Qᵢ' = Qᵢ Fᵢ
//                  v' = v + h/(2μ) (F + F'),   Πᵢ' = Fᵢᵀ (Πᵢ + h/2 Mᵢ) + h/2 Mᵢ'
//                with J_d = ∫ρρᵀ dm (second_moments), Πᵢ = Gᵢ and Mᵢ the torque, both in the body frame.
//                The implicit equation is solved in Cayley coordinates, Fᵢ = (1 + f̂)(1 − f̂)⁻¹: with
//                b = hΠ + h²/2 M it reads b + b × f + (b·f) f − 2 I f = 0 (I the principal moments),
//                by Newton's method to round-off. One force evaluation per step (F', M' serve the next).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "rotlie/models/scenes/binary_system.hpp"

namespace rotlie::models {

/// What both integrators hold: the system they step.
template <class T>
class binary_system_stepper {
 public:
  explicit binary_system_stepper(binary_system<T> system) : system_(std::move(system)) {}
  const binary_system<T>& system() const { return system_; }

 protected:
  binary_system<T> system_;
};

template <class T>
class binary_rk4 : public binary_system_stepper<T> {
 public:
  using binary_system_stepper<T>::binary_system_stepper;
  static constexpr int evaluations_per_step = 4;

  /// One step from time t.
  void step(binary_state<T>& x, const T& h, const T& t = T(0)) const {
    const auto k1 = this->system_.derivative(x, t);
    const auto k2 = this->system_.derivative(displaced(x, k1, h / 2), t + h / 2);
    const auto k3 = this->system_.derivative(displaced(x, k2, h / 2), t + h / 2);
    const auto k4 = this->system_.derivative(displaced(x, k3, h), t + h);
    x = displaced(x, k1, h / 6);
    x = displaced(x, k2, h / 3);
    x = displaced(x, k3, h / 3);
    x = displaced(x, k4, h / 6);
  }
};

template <class T>
class binary_lgvi : public binary_system_stepper<T> {
 public:
  using binary_system_stepper<T>::binary_system_stepper;
  static constexpr int evaluations_per_step = 1;

  /// One step from time t; `gravity` holds the forces at x on entry (valid = true) and at the new x on return.
  void step(binary_state<T>& x, const T& h, mutual_gravity<T>& gravity, bool& valid, const T& t = T(0)) const {
    if (!valid) gravity = this->system_.forces(x, t), valid = true;
    const T mu = this->system_.reduced_mass();
    vec3<T> torque[2];
    mat3<T> turn[2];
    for (int i = 0; i < 2; ++i) {
      torque[i] = transpose(x.body[i].Q) * (i == 0 ? gravity.M1 : gravity.M2);
      vec3<T> b;
      for (std::size_t k = 0; k < 3; ++k) b[k] = h * x.body[i].G[k] + h * h / 2 * torque[i][k];
      turn[i] = cayley(solve_turn(b, this->system_.moments(i)));
    }
    for (std::size_t k = 0; k < 3; ++k) x.r[k] += h * x.v[k] + h * h / (2 * mu) * gravity.F[k];
    for (int i = 0; i < 2; ++i) x.body[i].Q = x.body[i].Q * turn[i];
    const auto next = this->system_.forces(x, t + h);
    for (std::size_t k = 0; k < 3; ++k) x.v[k] += h / (2 * mu) * (gravity.F[k] + next.F[k]);
    for (int i = 0; i < 2; ++i) {
      const vec3<T> torque_next = transpose(x.body[i].Q) * (i == 0 ? next.M1 : next.M2);
      vec3<T> kicked;
      for (std::size_t k = 0; k < 3; ++k) kicked[k] = x.body[i].G[k] + h / 2 * torque[i][k];
      const vec3<T> turned = transpose(turn[i]) * kicked;
      for (std::size_t k = 0; k < 3; ++k) x.body[i].G[k] = turned[k] + h / 2 * torque_next[k];
    }
    gravity = next;
  }

 private:
  // Newton's method on g(f) = b + b × f + (b·f) f − 2 I f, Jacobian b̂ + f bᵀ + (b·f) 1 − 2 I.
  static vec3<T> solve_turn(const vec3<T>& b, const vec3<T>& I) {
    using std::abs;
    vec3<T> f{b[0] / (2 * I[0]), b[1] / (2 * I[1]), b[2] / (2 * I[2])};
    for (int iteration = 0; iteration < 50; ++iteration) {
      const T bf = dot(b, f);
      const vec3<T> bxf = cross(b, f);
      vec3<T> g;
      for (std::size_t k = 0; k < 3; ++k) g[k] = b[k] + bxf[k] + bf * f[k] - 2 * I[k] * f[k];
      mat3<T> J;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) J(i, j) = f[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)] + (i == j ? bf - 2 * I[static_cast<std::size_t>(i)] : T(0));
      J(0, 1) -= b[2], J(0, 2) += b[1], J(1, 0) += b[2], J(1, 2) -= b[0], J(2, 0) -= b[1], J(2, 1) += b[0];
      const vec3<T> delta = solve3(J, g);
      T size = 0, change = 0;
      for (std::size_t k = 0; k < 3; ++k) f[k] -= delta[k], size += abs(f[k]), change += abs(delta[k]);
      if (change <= 2 * std::numeric_limits<T>::epsilon() * size) return f;
    }
    throw std::runtime_error("LGVI: the implicit rotation did not converge (the step is too large for the spin)");
  }

  static vec3<T> solve3(const mat3<T>& A, const vec3<T>& y) {
    const T det = A(0, 0) * (A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1)) - A(0, 1) * (A(1, 0) * A(2, 2) - A(1, 2) * A(2, 0)) +
                  A(0, 2) * (A(1, 0) * A(2, 1) - A(1, 1) * A(2, 0));
    vec3<T> x;
    for (int c = 0; c < 3; ++c) {
      mat3<T> B = A;
      for (int r = 0; r < 3; ++r) B(r, c) = y[static_cast<std::size_t>(r)];
      x[static_cast<std::size_t>(c)] = (B(0, 0) * (B(1, 1) * B(2, 2) - B(1, 2) * B(2, 1)) - B(0, 1) * (B(1, 0) * B(2, 2) - B(1, 2) * B(2, 0)) +
                                        B(0, 2) * (B(1, 0) * B(2, 1) - B(1, 1) * B(2, 0))) /
                                       det;
    }
    return x;
  }

  // (1 + f̂)(1 − f̂)⁻¹ = 1 + 2 (f̂ + f̂²) / (1 + f·f)
  static mat3<T> cayley(const vec3<T>& f) {
    mat3<T> S;
    S(0, 1) = -f[2], S(0, 2) = f[1], S(1, 0) = f[2], S(1, 2) = -f[0], S(2, 0) = -f[1], S(2, 1) = f[0];
    const mat3<T> S2 = S * S;
    const T c = 2 / (1 + dot(f, f));
    mat3<T> F = mat3<T>::identity();
    for (std::size_t k = 0; k < 9; ++k) F.a[k] += c * (S.a[k] + S2.a[k]);
    return F;
  }
};

}  // namespace rotlie::models
