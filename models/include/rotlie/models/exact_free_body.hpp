#pragma once
// The exact motion of the free rigid body (REFERENCE.md §2.3, van Zon & Schofield's structure):
// the body momentum by Jacobi elliptic functions, the attitude by the rotation angle ψ about the
// angular momentum, in closed form with the incomplete elliptic integral of the third kind.
// Both energy regimes (a frame swap makes the momentum circulate about the working z axis), the
// separatrix (m = 1, hyperbolic functions), symmetric and spherical bodies and steady rotations
// are handled; the amplitude and Π are continued across multiples of K, so ψ never jumps.
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <algorithm>
#include <numeric>

#include "rotlie/models/rigid_body.hpp"

namespace rotlie::models {

template <class T>
class exact_free_body {
 public:
  exact_free_body(const vec3<T>& I, const body_state<T>& initial) : initial_(initial) {
    validate_moments(I);
    using std::abs;
    using std::atan2;
    using std::sqrt;
    // Working frame: a proper rotation W with moments (Ix, Iy, Iz), I_y the middle one, chosen so that
    // (L² − 2E I_y)(I_z − I_x) ≥ 0: the momentum circulates about the working z axis.
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return I[static_cast<std::size_t>(a)] < I[static_cast<std::size_t>(b)]; });
    const vec3<T>& G = initial.G;
    const T L2 = dot(G, G), two_e = 2 * kinetic_energy(I, G);
    if (!(I[static_cast<std::size_t>(order[0])] < I[static_cast<std::size_t>(order[2])])) {
      kind_ = motion::steady;  // spherical body: rotation about G at |G|/I
    } else {
      const T Iy = I[static_cast<std::size_t>(order[1])];
      // Σ G_i² (1 − I_y/I_i) = L² − 2E I_y, without cancellation
      T middle = 0;
      for (std::size_t i = 0; i < 3; ++i) middle += G[i] * G[i] * (1 - Iy / I[i]);
      if (middle < 0) std::swap(order[0], order[2]);  // U*: swap x and z, reverse y (below)
    }
    for (int r = 0; r < 3; ++r) W_(r, order[static_cast<std::size_t>(r)]) = T(1);
    if (det(W_) < 0)
      for (int c = 0; c < 3; ++c) W_(1, c) = -W_(1, c);
    for (std::size_t r = 0; r < 3; ++r) Iw_[r] = I[static_cast<std::size_t>(order[r])];
    const vec3<T> L = W_ * G;
    length_ = sqrt(L2);
    const vec3<T> w = angular_velocity(Iw_, L);
    const T cross = abs(L[0] * w[1] - L[1] * w[0]) + abs(L[1] * w[2] - L[2] * w[1]) + abs(L[2] * w[0] - L[0] * w[2]);
    if (kind_ == motion::steady || length_ == 0 || cross == 0) {
      kind_ = motion::steady;  // ω ∥ G: Q(t) = Q0 · rotation(ω/|ω|, |ω| t)
      const vec3<T> wb = angular_velocity(I, G);
      steady_rate_ = sqrt(dot(wb, wb));
      if (steady_rate_ > 0) steady_axis_ = {wb[0] / steady_rate_, wb[1] / steady_rate_, wb[2] / steady_rate_};
      return;
    }
    kind_ = motion::elliptic;
    const T Ix = Iw_[0], Iy = Iw_[1], Iz = Iw_[2];
    T Dx = 0, Dz = 0;  // L² − 2E I_x and 2E I_z − L², as sums without cancellation
    for (std::size_t i = 0; i < 3; ++i) {
      Dx += L[i] * L[i] * (1 - Ix / Iw_[i]);
      Dz += L[i] * L[i] * (Iz / Iw_[i] - 1);
    }
    (void)two_e;
    const T sz = L[2] < 0 ? T(-1) : T(1);
    Lxm_ = sqrt(Ix * Dz / (Iz - Ix));
    Lym_ = sqrt(Iy * Dz / (Iz - Iy));
    Lzm_ = sz * sqrt(Iz * Dx / (Iz - Ix));
    m_ = (Iy - Ix) * Dz / ((Iz - Iy) * Dx);
    if (m_ > 1) m_ = 1;  // round-off on the separatrix
    if (m_ < 0) m_ = 0;
    k_ = sqrt(m_);
    const T sign_p = sz * ((Iz - Iy) < 0 ? T(-1) : T(1));
    wp_ = sign_p * sqrt(Dx * (Iz - Iy) / (Ix * Iy * Iz));
    n_ = -Lzm_ * Lzm_ * m_ / (Lxm_ * Lxm_);  // Abramowitz–Stegun sign, n ≤ 0
    const T phi0 = atan2(L[1] * Lxm_, L[0] * Lym_);
    separatrix_ = m_ == 1;
    if (!separatrix_) {
      K_ = boost::math::ellint_1(k_);
      Pi_complete_ = boost::math::ellint_3(k_, n_);
    }
    eps_ = continued_F(phi0);
    Pi0_ = continued_Pi(phi0);
    psi_scale_ = length_ * (Iz - Ix) / (Ix * Iz * wp_);
    R0t_ = transpose(frame(L));
    A0w_ = W_ * transpose(initial.Q);  // van Zon's A = Qᵀ, in the working frame
  }

  /// The elliptic parameter m of the momentum's motion (0 for a steady rotation, 1 on the separatrix).
  T parameter() const { return kind_ == motion::steady ? T(0) : m_; }

  /// The state at time t (any sign).
  body_state<T> at(const T& t) const {
    if (kind_ == motion::steady) {
      body_state<T> s = initial_;
      if (steady_rate_ > 0) s.Q = initial_.Q * rotation(steady_axis_, steady_rate_ * t);
      return s;
    }
    using std::atan2;
    using std::cos;
    using std::sin;
    const T u = wp_ * t + eps_;
    T sn, cn, dn, am;
    if (separatrix_) {
      using std::cosh;
      using std::tanh;
      sn = tanh(u);
      cn = dn = 1 / cosh(u);
      am = atan2(sn, cn);
    } else {
      using std::round;
      const T j = round(u / (2 * K_));
      const T v = u - 2 * j * K_;
      sn = boost::math::jacobi_elliptic(k_, v, &cn, &dn);
      am = atan2(sn, cn) + j * boost::math::constants::pi<T>();  // cn(v) ≥ 0 on |v| ≤ K: continuous
      if (static_cast<long long>(j) % 2 != 0) sn = -sn, cn = -cn;  // sn, cn(v + 2jK) = (−1)^j sn, cn(v)
    }
    const vec3<T> L{Lxm_ * cn, Lym_ * sn, Lzm_ * dn};
    const T psi = length_ / Iw_[2] * t + psi_scale_ * (continued_Pi(am) - Pi0_);
    mat3<T> Z;
    Z(0, 0) = cos(psi), Z(0, 1) = sin(psi), Z(1, 0) = -sin(psi), Z(1, 1) = cos(psi), Z(2, 2) = T(1);
    const mat3<T> A = frame(L) * Z * R0t_ * A0w_;
    body_state<T> s;
    const mat3<T> Wt = transpose(W_);
    s.G = Wt * L;
    s.Q = transpose(Wt * A);
    return s;
  }

 private:
  enum class motion { steady, elliptic };

  static T det(const mat3<T>& m) {
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  }

  // R1(L) of REFERENCE.md §2.3: columns (L_x L_z/(L L⊥), L_y L_z/(L L⊥), −L⊥/L), (−L_y/L⊥, L_x/L⊥, 0), L/|L|.
  mat3<T> frame(const vec3<T>& L) const {
    using std::sqrt;
    const T perp = sqrt(L[0] * L[0] + L[1] * L[1]), l = length_;
    mat3<T> r;
    r(0, 0) = L[0] * L[2] / (l * perp), r(1, 0) = L[1] * L[2] / (l * perp), r(2, 0) = -perp / l;
    r(0, 1) = -L[1] / perp, r(1, 1) = L[0] / perp, r(2, 1) = 0;
    r(0, 2) = L[0] / l, r(1, 2) = L[1] / l, r(2, 2) = L[2] / l;
    return r;
  }

  // F(φ | m) continued: F(φ + jπ) = F(φ) + 2jK.
  T continued_F(const T& phi) const {
    using std::atanh;
    using std::round;
    using std::sin;
    if (separatrix_) return atanh(sin(phi));  // F(φ | 1) = artanh(sin φ), |φ| < π/2
    const T j = round(phi / boost::math::constants::pi<T>());
    return 2 * j * K_ + boost::math::ellint_1(k_, phi - j * boost::math::constants::pi<T>());
  }
  // Π(φ; n | m) continued: Π(φ + jπ) = Π(φ) + 2jΠ(n | m).
  T continued_Pi(const T& phi) const {
    using std::round;
    if (separatrix_) return boost::math::ellint_3(k_, n_, phi);
    const T j = round(phi / boost::math::constants::pi<T>());
    return 2 * j * Pi_complete_ + boost::math::ellint_3(k_, n_, phi - j * boost::math::constants::pi<T>());
  }

  body_state<T> initial_;
  motion kind_ = motion::elliptic;
  mat3<T> W_{}, R0t_{}, A0w_{};
  vec3<T> Iw_{}, steady_axis_{};
  T steady_rate_ = 0, length_ = 0;
  T Lxm_ = 0, Lym_ = 0, Lzm_ = 0, m_ = 0, k_ = 0, wp_ = 0, n_ = 0, K_ = 0, Pi_complete_ = 0, eps_ = 0, Pi0_ = 0, psi_scale_ = 0;
  bool separatrix_ = false;
};

}  // namespace rotlie::models
