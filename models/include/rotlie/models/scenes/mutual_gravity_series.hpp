#pragma once
// The mutual gravity of two rigid bodies at any order N: every term of total inertia-integral degree ≤ N
// (Hou, Scheeres & Xin 2017), with the force and both torques, on symmetric tensors stored as monomial
// moments (monomial_moments.hpp). With μ̃_α = μ_α/α! (α! = a! b! c!) and D_γ = ∂^γ(1/r), the term of body
// 2's degree k and body 1's degree m (k, m ∈ {0, 2, 3, …}, k + m = n ≤ N) of
//   U = −G Σ_n (1/n!) ⟨Dₙ, Sₙ⟩,  Sₙ = Σ_k C(n,k) (−1)^m T₂^(k) ⊗ T₁^(m)       (mutual_gravity.hpp)
// is, counting the index tuples of each monomial (k!/α! of them),
//   U_km = −G (−1)^m Σ_{|α|=k, |β|=m} D_{α+β} μ̃₂_α μ̃₁_β,
// the force on body 2 F = −∂U/∂r the same with D_{α+β+e_i}, and the torque on body 2 (a turn changes
// T^(k) by k ε δθ T, mutual_gravity.hpp) M_a = −G (−1)^m ε_abc Σ_{|γ|=k−1} (γ_c + 1) E_{γ+e_b} μ̃₂_{γ+e_c}
// with E_α = Σ_β D_{α+β} μ̃₁_β; body 1's alike. Every quantity is a contraction of tensors, so a term can
// be summed in either body's frame: in the frame of the body with the higher degree, whose integrals are
// then used as given, the other body's (degree ≤ N/2) turned into it. Only integrals of degree ≤ N/2
// are ever turned, and Dₙ is taken in both frames by the recurrence of ∂^α of r² ∂_i(1/r) = −x_i/r.
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/scenes/inertia_integrals.hpp"
#include "rotlie/models/scenes/monomial_moments.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// The highest order of the series (its cost grows as N⁶; the expansion converges only outside the
/// bodies' circumscribing spheres, where the terms fall as (size/r)^n).
constexpr int max_gravity_order = 16;

namespace series_detail {

/// The index of γ + β for every γ of degree g and β of degree m (g + m ≤ max_gravity_order + 1), flat:
/// of(g, m)[i·|m| + j] for the i-th monomial of degree g and the j-th of degree m.
class monomial_sums {
 public:
  static constexpr int top = max_gravity_order + 1;
  static const monomial_sums& get() {
    static const monomial_sums sums;
    return sums;
  }
  const int* of(int g, int m) const { return index_.data() + offset_[static_cast<std::size_t>(g * (top + 1) + m)]; }

 private:
  monomial_sums() : offset_(static_cast<std::size_t>((top + 1) * (top + 1)), 0) {
    const auto& table = monomial_table::get();
    for (int g = 0; g <= top; ++g)
      for (int m = 0; g + m <= top; ++m) {
        offset_[static_cast<std::size_t>(g * (top + 1) + m)] = index_.size();
        for (int i = first_monomial(g); i < first_monomial(g + 1); ++i)
          for (int j = first_monomial(m); j < first_monomial(m + 1); ++j) {
            const auto &a = table.exponents[static_cast<std::size_t>(i)], &b = table.exponents[static_cast<std::size_t>(j)];
            index_.push_back(monomial_index(a[0] + b[0], a[1] + b[1], a[2] + b[2]));
          }
      }
  }
  std::vector<int> index_;
  std::vector<std::size_t> offset_;
};

/// D_γ = ∂^γ(1/r) at x for every |γ| ≤ top. Applying ∂^α to r² ∂_i φ = −x_i φ (φ = 1/r) gives
/// r² D_{α+e_i} = −x_i D_α − α_i D_{α−e_i} − Σ_j [2 α_j x_j D_{α−e_j+e_i} + α_j(α_j − 1) D_{α−2e_j+e_i}],
/// every term on the right of degree |α| or |α| − 1. The plan holds, per γ, which i and which terms.
class derivative_plan {
 public:
  /// D_γ r² = Σ_t weight_t · x4[axis_t] · D[index_t], x4 = (x, y, z, 1); unused terms weigh 0
  struct step {
    int index[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    int axis[8] = {3, 3, 3, 3, 3, 3, 3, 3};
    double weight[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  };
  static const derivative_plan& get() {
    static const derivative_plan plan;
    return plan;
  }
  const std::vector<step>& steps() const { return steps_; }

 private:
  derivative_plan() {
    const auto& table = monomial_table::get();
    for (int g = 1; g < monomials_up_to(max_gravity_order + 1); ++g) {
      std::array<int, 3> a = table.exponents[static_cast<std::size_t>(g)];
      step s;
      int t = 0;
      const auto add = [&](const std::array<int, 3>& e, int axis, int weight) {
        s.index[t] = monomial_index(e[0], e[1], e[2]), s.axis[t] = axis, s.weight[t] = -weight, ++t;
      };
      const std::size_t i = a[0] > 0 ? 0 : a[1] > 0 ? 1 : 2;
      --a[i];  // α = γ − e_i
      add(a, static_cast<int>(i), 1);
      for (std::size_t j = 0; j < 3; ++j) {
        if (a[j] == 0) continue;
        auto b = a;
        --b[j];
        if (j == i) add(b, 3, a[j]);  // α_i D_{α−e_i}
        ++b[i];
        add(b, static_cast<int>(j), 2 * a[j]);  // 2 α_j x_j D_{α−e_j+e_i}
        if (a[j] >= 2) {
          --b[j];
          add(b, 3, a[j] * (a[j] - 1));  // α_j(α_j − 1) D_{α−2e_j+e_i}
        }
      }
      steps_.push_back(s);
    }
  }
  std::vector<step> steps_;
};

template <class T>
void inverse_distance_derivatives(const vec3<T>& x, int top, T* D) {
  using std::sqrt;
  const auto& steps = derivative_plan::get().steps();
  const T r2 = dot(x, x), inverse_r2 = 1 / r2;
  const T x4[4] = {x[0] * inverse_r2, x[1] * inverse_r2, x[2] * inverse_r2, inverse_r2};
  D[0] = 1 / sqrt(r2);
  for (int g = 1; g < monomials_up_to(top); ++g) {
    const auto& s = steps[static_cast<std::size_t>(g - 1)];
    T sum = 0;
    for (int t = 0; t < 8; ++t) sum += T(s.weight[t]) * x4[s.axis[t]] * D[s.index[t]];
    D[g] = sum;
  }
}

/// For a full rank-k tensor: each index tuple's monomial, and each monomial's first tuple.
class tensor_layout {
 public:
  static constexpr int top = max_gravity_order / 2;
  static const tensor_layout& get() {
    static const tensor_layout layout;
    return layout;
  }
  const std::vector<int>& monomial_of(int k) const { return monomial_of_[static_cast<std::size_t>(k)]; }
  const std::vector<std::size_t>& tuple_of(int k) const { return tuple_of_[static_cast<std::size_t>(k)]; }

 private:
  tensor_layout() {
    const auto& table = monomial_table::get();
    for (int k = 0; k <= top; ++k) {
      std::size_t size = 1;
      for (int p = 0; p < k; ++p) size *= 3;
      std::vector<int> monomials(size);
      for (std::size_t index = 0; index < size; ++index) {
        int count[3] = {0, 0, 0};
        for (std::size_t rest = index, slot = 0; slot < static_cast<std::size_t>(k); ++slot, rest /= 3) ++count[rest % 3];
        monomials[index] = monomial_index(count[0], count[1], count[2]);
      }
      std::vector<std::size_t> tuples;
      for (int m = first_monomial(k); m < first_monomial(k + 1); ++m) {
        const auto& e = table.exponents[static_cast<std::size_t>(m)];
        std::size_t index = 0;
        for (std::size_t axis = 0; axis < 3; ++axis)
          for (int p = 0; p < e[axis]; ++p) index = 3 * index + axis;
        tuples.push_back(index);
      }
      monomial_of_.push_back(std::move(monomials));
      tuple_of_.push_back(std::move(tuples));
    }
  }
  std::vector<std::vector<int>> monomial_of_;
  std::vector<std::vector<std::size_t>> tuple_of_;
};

/// The scaled moments μ̃ of degree k turned by R (x' = R x), from the scaled moments in the body frame:
/// through the full tensor, one slot at a time (3^k·3k products; k ≤ N/2 here).
template <class T>
void turn_scaled_moments(const mat3<T>& R, const T* scaled, int k, T* out, std::vector<T>& full, std::vector<T>& next) {
  const auto& table = monomial_table::get();
  const auto& layout = tensor_layout::get();
  const auto& monomials = layout.monomial_of(k);
  const std::size_t size = monomials.size();
  full.resize(size), next.resize(size);
  for (std::size_t index = 0; index < size; ++index) {
    const auto m = static_cast<std::size_t>(monomials[index]);
    full[index] = scaled[m] * T(table.factorial[m]);
  }
  for (std::size_t stride = size / 3; stride >= 1; stride /= 3) {
    for (std::size_t block = 0; block < size; block += 3 * stride)
      for (std::size_t offset = 0; offset < stride; ++offset) {
        const std::size_t base = block + offset;
        const T x = full[base], y = full[base + stride], z = full[base + 2 * stride];
        for (std::size_t a = 0; a < 3; ++a)
          next[base + a * stride] = R(static_cast<int>(a), 0) * x + R(static_cast<int>(a), 1) * y + R(static_cast<int>(a), 2) * z;
      }
    full.swap(next);
  }
  const auto& tuples = layout.tuple_of(k);
  for (int m = first_monomial(k), i = 0; m < first_monomial(k + 1); ++m, ++i)
    out[m] = full[tuples[static_cast<std::size_t>(i)]] / T(table.factorial[static_cast<std::size_t>(m)]);
}

/// Buffers reused from one evaluation to the next (one per thread): no allocation once warm.
template <class T>
struct series_workspace {
  std::vector<T> mu1, mu2, mu1_in_2, mu2_in_1, D1, D2, S, E, full, next;
  void reserve(int order) {
    const auto moments = static_cast<std::size_t>(monomials_up_to(order)), derivatives = static_cast<std::size_t>(monomials_up_to(order + 1));
    for (auto* v : {&mu1, &mu2, &mu1_in_2, &mu2_in_1})
      if (v->size() < moments) v->resize(moments);
    for (auto* v : {&D1, &D2})
      if (v->size() < derivatives) v->resize(derivatives);
    const auto widest = static_cast<std::size_t>(2 * monomials_of_degree(order + 1));
    if (E.size() < widest) E.resize(widest);
    if (S.size() < widest) S.resize(widest);
  }
};

/// M_a += c ε_abc Σ_{|γ|=k−1} (γ_c + 1) E_{γ+e_b} μ̃_{γ+e_c}, E and μ̃ of degree k (E indexed from its degree's first).
template <class T>
void add_torque(vec3<T>& M, const T& c, const T* E, const T* scaled, int k) {
  const auto& table = monomial_table::get();
  const int* up = monomial_sums::get().of(k - 1, 1);
  const int first = first_monomial(k);
  T B[3][3] = {};
  for (int g = first_monomial(k - 1), i = 0; g < first; ++g, ++i) {
    const auto& e = table.exponents[static_cast<std::size_t>(g)];
    for (int b = 0; b < 3; ++b) {
      const T Eb = E[up[3 * i + b] - first];
      for (int cc = 0; cc < 3; ++cc) B[b][cc] += T(e[static_cast<std::size_t>(cc)] + 1) * Eb * scaled[up[3 * i + cc]];
    }
  }
  M[0] += c * (B[1][2] - B[2][1]);
  M[1] += c * (B[2][0] - B[0][2]);
  M[2] += c * (B[0][1] - B[1][0]);
}

/// out_γ = Σ_β D_{γ+β} B_β over |γ| = g, |β| = m (out indexed from degree g's first).
template <class T>
void contract(const T* D, const T* B, int g, int m, T* out) {
  const int* sum = monomial_sums::get().of(g, m);
  const int rows = monomials_of_degree(g), columns = monomials_of_degree(m);
  const T* b = B + first_monomial(m);
  for (int i = 0; i < rows; ++i, sum += columns) {
    T s = 0;
    for (int j = 0; j < columns; ++j) s += D[sum[j]] * b[j];
    out[i] = s;
  }
}

}  // namespace series_detail

/// U, the force on body 2 and both torques (as mutual_gravity_at) summed over every term of degree ≤ order,
/// any order to max_gravity_order. Without `point_masses` the n = 0 term is left out.
template <class T>
void mutual_gravity_series(const gravitating_body<T>& b1, const mat3<T>& Q1, const gravitating_body<T>& b2, const mat3<T>& Q2, const vec3<T>& r,
                           const T& G, int order, bool point_masses, T& U, vec3<T>& F, vec3<T>& M1, vec3<T>& M2) {
  using namespace series_detail;
  if (order < 0 || order > max_gravity_order)
    throw std::invalid_argument("mutual gravity: order " + std::to_string(order) + " (0 to " + std::to_string(max_gravity_order) + ")");
  const auto& table = monomial_table::get();
  thread_local series_workspace<T> w;
  w.reserve(order);
  body_moments(b1, order, w.mu1.data());
  body_moments(b2, order, w.mu2.data());
  for (std::size_t i = 0; i < static_cast<std::size_t>(monomials_up_to(order)); ++i) {
    if constexpr (sizeof(T) <= sizeof(long double)) {  // a product is cheaper than a quotient
      w.mu1[i] *= T(table.inverse_factorial[i]), w.mu2[i] *= T(table.inverse_factorial[i]);
    } else {  // wider than the table's numbers: divide by the exact factorial
      w.mu1[i] /= T(table.factorial[i]), w.mu2[i] /= T(table.factorial[i]);
    }
  }
  const mat3<T> to_1 = transpose(Q1), to_2 = transpose(Q2);
  inverse_distance_derivatives(to_1 * r, order + 1, w.D1.data());
  inverse_distance_derivatives(to_2 * r, order + 1, w.D2.data());
  using std::sqrt;
  // body 2's integrals of degree ≤ N/2 in body 1's frame, body 1's of degree < N/2 in body 2's
  const mat3<T> two_to_one = to_1 * Q2, one_to_two = to_2 * Q1;
  w.mu2_in_1[0] = w.mu2[0], w.mu1_in_2[0] = w.mu1[0];
  for (int k = 2; 2 * k <= order; ++k) turn_scaled_moments(two_to_one, w.mu2.data(), k, w.mu2_in_1.data(), w.full, w.next);
  for (int k = 2; 2 * k < order; ++k) turn_scaled_moments(one_to_two, w.mu1.data(), k, w.mu1_in_2.data(), w.full, w.next);
  // per frame and degree n: S̃_γ = Σ_terms c Σ_{α+β=γ} μ̃₂_α μ̃₁_β, then U = Σ D_γ S̃_γ and F_i = −Σ D_{γ+e_i} S̃_γ
  const auto& sums = monomial_sums::get();
  // a degree whose integrals all vanish (an ellipsoid's odd ones) vanishes in any frame: its terms are skipped
  bool present[2][max_gravity_order + 1];
  for (int k = 0; k <= order; ++k) {
    present[0][k] = present[1][k] = false;
    for (int i = first_monomial(k); i < first_monomial(k + 1); ++i) {
      present[0][k] = present[0][k] || w.mu1[static_cast<std::size_t>(i)] != T(0);
      present[1][k] = present[1][k] || w.mu2[static_cast<std::size_t>(i)] != T(0);
    }
  }
  vec3<T> F_in[2] = {}, M1_in[2] = {}, M2_in[2] = {};
  U = 0;
  vec3<T> F_point{};
  if (point_masses) {  // n = 0, inertial: Newton's
    const T inverse_r = 1 / sqrt(dot(r, r)), g = G * w.mu1[0] * w.mu2[0];
    U = -g * inverse_r;
    for (std::size_t axis = 0; axis < 3; ++axis) F_point[axis] = -g * r[axis] * inverse_r * inverse_r * inverse_r;
  }
  for (int n = 2; n <= order; ++n) {
    const int width = monomials_of_degree(n);
    T* S[2] = {w.S.data(), w.S.data() + width};
    for (int i = 0; i < 2 * width; ++i) w.S[static_cast<std::size_t>(i)] = 0;
    for (int k = 0; k <= n; ++k) {
      const int m = n - k;
      if (k == 1 || m == 1 || !present[1][k] || !present[0][m]) continue;  // the first degree vanishes about the centres
      const int f = k > m ? 1 : 0;     // the frame of the body with the higher degree
      const T* D = f ? w.D2.data() : w.D1.data();
      const T* A = f ? w.mu2.data() : w.mu2_in_1.data();  // body 2's, degree k
      const T* B = f ? w.mu1_in_2.data() : w.mu1.data();  // body 1's, degree m
      const T c = m % 2 ? G : -G;                         // −G (−1)^m
      const int* sum = sums.of(k, m);
      const int columns = monomials_of_degree(m), first = first_monomial(n);
      const T* a = A + first_monomial(k);
      const T* b = B + first_monomial(m);
      T* Sf = S[f] - first;
      for (int i = 0; i < monomials_of_degree(k); ++i, sum += columns) {
        if (a[i] == T(0)) continue;
        const T ca = c * a[i];
        for (int j = 0; j < columns; ++j) Sf[sum[j]] += ca * b[j];
      }
      // the torque on the turned body (the lower degree); the other's follows from the frame's balance
      if (f == 0 && k >= 2) {
        contract(D, B, k, m, w.E.data());
        add_torque(M2_in[0], c, w.E.data(), A, k);
      }
      if (f == 1 && m >= 2) {
        contract(D, A, m, k, w.E.data());
        add_torque(M1_in[1], c, w.E.data(), B, m);
      }
    }
    const int* up = sums.of(n, 1);
    for (int f = 0; f < 2; ++f) {
      const T* D = f ? w.D2.data() : w.D1.data();
      T u = 0, force[3] = {0, 0, 0};
      for (int i = 0; i < width; ++i) {
        const T x = S[f][i];
        u += D[first_monomial(n) + i] * x;
        for (int axis = 0; axis < 3; ++axis) force[axis] += D[up[3 * i + axis]] * x;
      }
      U += u;
      for (std::size_t axis = 0; axis < 3; ++axis) F_in[f][axis] -= force[axis];
    }
  }
  // the terms summed in one frame are a potential invariant under a common turn of r and both bodies,
  // so they balance by themselves: r_f × F_f + M1_f + M2_f = 0 gives the torque on the frame's own body
  const vec3<T> r_in[2] = {to_1 * r, to_2 * r};
  for (int f = 0; f < 2; ++f) {
    const vec3<T>& x = r_in[f];
    const vec3<T>& y = F_in[f];
    const vec3<T> moment{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    vec3<T>& own = f == 0 ? M1_in[0] : M2_in[1];
    const vec3<T>& other = f == 0 ? M2_in[0] : M1_in[1];
    for (std::size_t axis = 0; axis < 3; ++axis) own[axis] = -moment[axis] - other[axis];
  }
  const auto inertial = [&](const vec3<T> (&in)[2]) {
    const auto a = Q1 * in[0], b = Q2 * in[1];
    return vec3<T>{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  };
  F = inertial(F_in), M1 = inertial(M1_in), M2 = inertial(M2_in);
  for (std::size_t axis = 0; axis < 3; ++axis) F[axis] += F_point[axis];
}

}  // namespace rotlie::models
