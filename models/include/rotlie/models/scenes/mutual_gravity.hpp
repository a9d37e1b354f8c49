#pragma once
// The mutual gravity of two rigid bodies (the full two-body problem of binary asteroids), expanded in
// the bodies' inertia integrals T^(k) (inertia_integrals.hpp) and truncated by total degree N (Hou,
// Scheeres & Xin 2017): written out on full tensors for N = 0, 2, 4 (below, the fast path), any N to
// max_gravity_order by the series on monomial moments (mutual_gravity_series.hpp). With ρ₁, ρ₂ the mass elements' offsets from the centres (inertial frame)
// and r = x₂ − x₁, 1/|r + ρ₂ − ρ₁| expanded in Taylor series about r gives
//   U = −G Σ_n (1/n!) ⟨Dₙ, Sₙ⟩,  Dₙ = ∂ⁿ(1/r),  Sₙ = Σ_k C(n,k) (−1)^(n−k) T₂^(k) ⊗ T₁^(n−k),
// so that, with T^(0) = M and T^(1) = 0,
//   S₀ = M₁M₂,  S₂ = M₁J₂ + M₂J₁,  S₃ = M₁T₂^(3) − M₂T₁^(3),  S₄ = M₁T₂^(4) + 6 J₂⊗J₁ + M₂T₁^(4).
// Order 2 is MacCullagh's formula for each body; order 4 adds the third- and fourth-degree integrals
// and the product of the two bodies' second-degree ones (terms up to 1/r⁵). The force on body 2 is
// F = −∂U/∂r = G Σ (1/n!) ⟨D_{n+1}, Sₙ⟩ (−F on body 1). A term ⟨A, T_i^(k)⟩ of U changes under a turn
// δθ of body i by k ε_{abc} δθ_a A_{b…} T_{c…}, so the torque about the body's centre (inertial) is
// M_a = k ε_{abc} B_{bc}, B_{bc} = A_{b i₂…} T_{c i₂…}. U is invariant under a common rotation of
// r, ρ₁ and ρ₂, hence r × F + M₁ + M₂ = 0: the total angular momentum is conserved.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/inertia_integrals.hpp"
#include "rotlie/models/scenes/mutual_gravity_series.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// U, the force on body 2 and each body's torque about its own centre (inertial frame).
template <class T>
struct mutual_gravity {
  T U{};
  vec3<T> F{}, M1{}, M2{};
};

/// Throws std::invalid_argument unless the expansion can be taken to this order.
inline void check_gravity_order(int order) {
  if (order < 0 || order > max_gravity_order)
    throw std::invalid_argument("mutual gravity: order " + std::to_string(order) + " (0 to " + std::to_string(max_gravity_order) + ")");
}

/// Whether the order is evaluated written out on full tensors rather than summed as the series: the
/// series is faster from order 4 on (1.0 µs against 4.6 µs an evaluation at order 4, bench/gravity_bench.cpp).
inline bool gravity_order_written_out(int order) { return order == 0 || order == 2; }

/// Throws std::invalid_argument when the body lacks the integrals the order needs (a point mass has them all).
template <class T>
void check_body_integrals(const gravitating_body<T>& body, int order, const std::string& name) {
  bool point = true;
  for (const auto& x : body.inertia.a) point = point && x == T(0);
  if (order > body.degree && !point)
    throw std::invalid_argument("mutual gravity at order " + std::to_string(order) + ": the " + name + " is given by its integrals to degree " +
                                std::to_string(body.degree) + " only");
  if (order > 4 && !point && body.moments.size() < static_cast<std::size_t>(monomials_up_to(order)))
    throw std::invalid_argument("mutual gravity at order " + std::to_string(order) + ": the " + name + " carries no moments of degree above 4");
}

namespace gravity_detail {

/// ∂ⁿ(1/r) at x, every component: Σ over the ways m pairs of the n slots carry δ's and the rest x's,
/// (−1)^(n−m) (2n−2m−1)!! x^… / r^(2n−2m+1). A component depends only on how many slots hold each axis.
template <class T, int N>
tensor3<T, N> inverse_distance_derivative(const vec3<T>& x, const T& inverse_r) {
  static_assert(N <= 5);
  T x_power[3][N + 1], r_power[2 * N + 2];
  for (int k = 0; k < 3; ++k) {
    x_power[k][0] = 1;
    for (int p = 1; p <= N; ++p) x_power[k][p] = x_power[k][p - 1] * x[static_cast<std::size_t>(k)];
  }
  r_power[0] = 1;
  for (int p = 1; p <= 2 * N + 1; ++p) r_power[p] = r_power[p - 1] * inverse_r;
  // pairings(p, a) = p! / (2^a a! (p − 2a)!): the ways to pick a disjoint pairs among p slots
  constexpr long pairings[6][3] = {{1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 3, 0}, {1, 6, 3}, {1, 10, 15}};
  constexpr long odd_double_factorial[6] = {1, 1, 3, 15, 105, 945};  // (2j − 1)!!
  T by_count[N + 1][N + 1];
  for (int p = 0; p <= N; ++p)
    for (int q = 0; p + q <= N; ++q) {
      const int s = N - p - q;
      T sum = 0;
      for (int a = 0; 2 * a <= p; ++a)
        for (int b = 0; 2 * b <= q; ++b)
          for (int c = 0; 2 * c <= s; ++c) {
            const int m = a + b + c;
            const long weight = odd_double_factorial[N - m] * pairings[p][a] * pairings[q][b] * pairings[s][c];
            const T term = T(weight) * r_power[2 * N - 2 * m + 1] * x_power[0][p - 2 * a] * x_power[1][q - 2 * b] * x_power[2][s - 2 * c];
            sum += (N - m) % 2 ? -term : term;
          }
      by_count[p][q] = sum;
    }
  tensor3<T, N> out;
  for (std::size_t index = 0; index < out.size(); ++index) {
    int count[3] = {0, 0, 0};
    for (std::size_t rest = index, slot = 0; slot < static_cast<std::size_t>(N); ++slot, rest /= 3) ++count[rest % 3];
    out[index] = by_count[count[0]][count[1]];
  }
  return out;
}

/// ⟨D, S⟩ over all of S's slots, D's remaining leading slots free: out[i] = Σ_J D[i·|S| + J] S[J].
template <class T, std::size_t ND, std::size_t NS>
std::array<T, ND / NS> contract(const std::array<T, ND>& D, const std::array<T, NS>& S) {
  std::array<T, ND / NS> out{};
  for (std::size_t i = 0; i < out.size(); ++i) {
    T sum = 0;
    for (std::size_t j = 0; j < S.size(); ++j) sum += D[i * S.size() + j] * S[j];
    out[i] = sum;
  }
  return out;
}

template <class T, std::size_t N>
std::array<T, N> scaled(const std::array<T, N>& t, const T& factor) {
  std::array<T, N> out;
  for (std::size_t i = 0; i < t.size(); ++i) out[i] = factor * t[i];
  return out;
}

template <class T, std::size_t N>
void add_to(std::array<T, N>& sum, const std::array<T, N>& t, const T& factor) {
  for (std::size_t i = 0; i < t.size(); ++i) sum[i] += factor * t[i];
}

template <class T>
tensor3<T, 2> flat(const mat3<T>& m) {
  return m.a;
}

/// The torque of a term ⟨A, T^(k)⟩ of U on its body: M_a += k ε_{abc} A_{b…} T_{c…}.
template <class T, int K>
void add_torque(vec3<T>& M, const tensor3<T, K>& A, const tensor3<T, K>& t) {
  constexpr std::size_t rest = power_of_three(K - 1);
  T B[3][3];
  for (std::size_t b = 0; b < 3; ++b)
    for (std::size_t c = 0; c < 3; ++c) {
      T sum = 0;
      for (std::size_t j = 0; j < rest; ++j) sum += A[b * rest + j] * t[c * rest + j];
      B[b][c] = sum;
    }
  M[0] += K * (B[1][2] - B[2][1]);
  M[1] += K * (B[2][0] - B[0][2]);
  M[2] += K * (B[0][1] - B[1][0]);
}

}  // namespace gravity_detail

/// The expansion written out on full tensors at order 0, 2 or 4 (the series' second code, and the
/// faster one at orders 0 and 2).
template <class T>
mutual_gravity<T> mutual_gravity_written_out(const gravitating_body<T>& b1, const mat3<T>& Q1, const gravitating_body<T>& b2, const mat3<T>& Q2,
                                             const vec3<T>& r, const T& G, int order, bool point_masses = true) {
  using namespace gravity_detail;
  if (order != 0 && order != 2 && order != 4)
    throw std::invalid_argument("mutual gravity written out: order " + std::to_string(order) + " (0, 2 or 4)");
  using std::sqrt;
  const T inverse_r = 1 / sqrt(dot(r, r));
  const T m1 = b1.mass, m2 = b2.mass;
  mutual_gravity<T> out;
  if (point_masses) {
    out.U = -G * m1 * m2 * inverse_r;
    const auto D1 = inverse_distance_derivative<T, 1>(r, inverse_r);
    for (std::size_t k = 0; k < 3; ++k) out.F[k] = G * m1 * m2 * D1[k];  // −∂U/∂r: attraction toward body 1
  }
  if (order == 0) return out;
  check_body_integrals(b1, order, "primary");
  check_body_integrals(b2, order, "secondary");
  // the second-degree integrals in the inertial frame: J' = Q J Qᵀ
  const auto J1 = flat(Q1 * second_moments(b1.inertia) * transpose(Q1)), J2 = flat(Q2 * second_moments(b2.inertia) * transpose(Q2));
  const auto D2 = inverse_distance_derivative<T, 2>(r, inverse_r);
  const auto D3 = inverse_distance_derivative<T, 3>(r, inverse_r);
  tensor3<T, 2> S2 = scaled(J2, m1);
  add_to(S2, J1, m2);
  out.U -= G / 2 * contract(D2, S2)[0];
  const auto F2 = contract(D3, S2);
  for (std::size_t k = 0; k < 3; ++k) out.F[k] += G / 2 * F2[k];
  // the torques' tensors A (U ⊃ ⟨A, J_i⟩): −(G M_j / 2) D₂, and at order 4 −(G/4) D₄:J_j
  tensor3<T, 2> A1 = scaled(D2, -G * m2 / 2), A2 = scaled(D2, -G * m1 / 2);
  if (order == 4) {
    const auto T1 = rotate_tensor<T, 3>(Q1, b1.third), T2 = rotate_tensor<T, 3>(Q2, b2.third);
    const auto F1 = rotate_tensor<T, 4>(Q1, b1.fourth), F2b = rotate_tensor<T, 4>(Q2, b2.fourth);
    const auto D4 = inverse_distance_derivative<T, 4>(r, inverse_r);
    const auto D5 = inverse_distance_derivative<T, 5>(r, inverse_r);
    tensor3<T, 3> S3 = scaled(T2, m1);
    add_to(S3, T1, -m2);
    tensor3<T, 4> S4 = scaled(F2b, m1);
    add_to(S4, F1, m2);
    for (std::size_t i = 0; i < 9; ++i)
      for (std::size_t j = 0; j < 9; ++j) S4[i * 9 + j] += 6 * J2[i] * J1[j];
    out.U -= G / 6 * contract(D3, S3)[0] + G / 24 * contract(D4, S4)[0];
    const auto F3 = contract(D4, S3);
    const auto F4 = contract(D5, S4);
    for (std::size_t k = 0; k < 3; ++k) out.F[k] += G / 6 * F3[k] + G / 24 * F4[k];
    add_to(A1, contract(D4, J2), -G / 4);
    add_to(A2, contract(D4, J1), -G / 4);
    add_torque<T, 3>(out.M1, scaled(D3, G * m2 / 6), T1);
    add_torque<T, 3>(out.M2, scaled(D3, -G * m1 / 6), T2);
    add_torque<T, 4>(out.M1, scaled(D4, -G * m2 / 24), F1);
    add_torque<T, 4>(out.M2, scaled(D4, -G * m1 / 24), F2b);
  }
  add_torque<T, 2>(out.M1, A1, J1);
  add_torque<T, 2>(out.M2, A2, J2);
  return out;
}

/// The mutual potential, force and torques truncated at `order` (0 to max_gravity_order). Without the
/// point masses' term (`point_masses` false) what is left is U − U₀, the perturbation of a Kepler split.
template <class T>
mutual_gravity<T> mutual_gravity_at(const gravitating_body<T>& b1, const mat3<T>& Q1, const gravitating_body<T>& b2, const mat3<T>& Q2,
                                    const vec3<T>& r, const T& G, int order, bool point_masses = true) {
  check_gravity_order(order);
  if (gravity_order_written_out(order)) return mutual_gravity_written_out(b1, Q1, b2, Q2, r, G, order, point_masses);
  check_body_integrals(b1, order, "primary");
  check_body_integrals(b2, order, "secondary");
  mutual_gravity<T> out;
  mutual_gravity_series(b1, Q1, b2, Q2, r, G, order, point_masses, out.U, out.F, out.M1, out.M2);
  return out;
}

/// The pair as the md engine's potential: bodies 0 and 1 of a rigid_bodies_state, each body's frame
/// its principal axes (the engine's rotors turn bodies about their principal moments).
template <class T>
class full_two_body_gravity {
 public:
  full_two_body_gravity(const gravitating_body<T>& b1, const gravitating_body<T>& b2, const T& G, int order)
      : b1_(b1), b2_(b2), G_(G), order_(order) {
    check_gravity_order(order);
    if (order > 0) check_body_integrals(b1, order, "primary"), check_body_integrals(b2, order, "secondary");
  }
  /// Bodies given by their principal moments alone (order 0 or 2).
  full_two_body_gravity(const T& m1, const vec3<T>& I1, const T& m2, const vec3<T>& I2, const T& G, int order)
      : full_two_body_gravity(gravitating_body<T>{m1, principal(I1)}, gravitating_body<T>{m2, principal(I2)}, G, order) {}

  bool acts() const { return true; }

  T evaluate(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque) const {
    if (bodies.size() != 2) throw std::invalid_argument("the full two-body problem has two bodies, not " + std::to_string(bodies.size()));
    const vec3<T> r{bodies[1].q[0] - bodies[0].q[0], bodies[1].q[1] - bodies[0].q[1], bodies[1].q[2] - bodies[0].q[2]};
    const auto g = mutual_gravity_at(b1_, bodies[0].rot.Q, b2_, bodies[1].rot.Q, r, G_, order_);
    force[0] = {-g.F[0], -g.F[1], -g.F[2]};
    force[1] = g.F;
    torque[0] = g.M1;
    torque[1] = g.M2;
    return g.U;
  }

 private:
  static mat3<T> principal(const vec3<T>& I) {
    mat3<T> m;
    for (int k = 0; k < 3; ++k) m(k, k) = I[static_cast<std::size_t>(k)];
    return m;
  }
  gravitating_body<T> b1_, b2_;
  T G_;
  int order_;
};

}  // namespace rotlie::models
