#pragma once
// The closed-form motion of the free rigid body in one scalar S (REFERENCE.md §2.3, van Zon &
// Schofield's structure): the body momentum by Jacobi elliptic functions about the working z axis,
// the attitude by the rotation angle ψ about the angular momentum. Written so that nothing
// degenerates where the elliptic parametrisation does:
//  - every Δ is a sum of same-sign terms with moment differences taken directly (Leroy's form), but
//    D_y, which cancels near the separatrix and is summed exactly instead, and
//    m_c = (I_z − I_x) D_y / ((I_z − I_y) D_x) is never formed as 1 − m;
//  - the initial phase near u = ±K (the homoclinic point, where F has its logarithmic singularity)
//    is found from the complementary argument sn(K − v) = cd v, cn(K − v) = k' sd v;
//  - Π(am u) − u is quasi-periodic and, for |v| > K/2 near m = 1, taken from the characteristic
//    transformation n → N = (m − n)/(1 − n) (A&S 17.7.16) at the complementary argument;
//  - ψ = (L/I_x) t + ψ_s [D(u) − D(u₀)] with D = Π − F ∝ n when |n| ≤ 1, or (L/I_z) t + ψ_s [Π(u) − Π(u₀)]
//    otherwise: the large parts of both forms are exact rates, the elliptic part carries the anisotropy;
//  - the separatrix (m_c = 0) uses tanh, sech and a closed-form ψ, on either branch.
// The caller (exact_free_body) scales |G| and I to O(1) by powers of two and picks S.
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <limits>

#include "rotlie/models/complementary_elliptic.hpp"
#include "rotlie/models/exact_energy_difference.hpp"
#include "rotlie/models/rigid_body.hpp"

namespace rotlie::models::detail {

template <class S>
class free_body_motion {
 public:
  free_body_motion(const vec3<S>& I, const vec3<S>& G, const mat3<S>& Q0) : Q0_(Q0), G0_(G) {
    using std::abs;
    using std::isfinite;
    using std::sqrt;
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return I[idx(a)] < I[idx(b)]; });
    if (!(I[idx(order[0])] < I[idx(order[2])])) {
      set_steady(I, G);  // spherical body
      return;
    }
    // Working frame: the momentum circulates about z when D_y = Σ G_i² (I_i − I_y)/I_i ≥ 0; else U*.
    // D_y is exact to its last place (it cancels near the separatrix): the branch and m_c stay right
    // down to any distance from the separatrix the inputs can express.
    bool Dy_inexact = false;  // only when its terms underflow: then a wider scalar is needed
    const S Dy = middle_energy_difference<S>(I, G, idx(order[0]), idx(order[1]), idx(order[2]), Dy_inexact);
    if (Dy < 0) std::swap(order[0], order[2]);
    for (int r = 0; r < 3; ++r) W_(r, order[idx(r)]) = S(1);
    if (det(W_) < 0)
      for (int c = 0; c < 3; ++c) W_(1, c) = -W_(1, c);
    for (std::size_t r = 0; r < 3; ++r) Iw_[r] = I[idx(order[r])];
    const vec3<S> L = W_ * G;
    length_ = sqrt(dot(L, L));
    const S Ix = Iw_[0], Iy = Iw_[1], Iz = Iw_[2];
    const vec3<S> w = angular_velocity(Iw_, L);
    if (length_ == 0 || (L[0] * w[1] - L[1] * w[0] == 0 && L[1] * w[2] - L[2] * w[1] == 0 && L[2] * w[0] - L[0] * w[2] == 0)) {
      set_steady(I, G);  // ω ∥ G
      return;
    }
    const S tiny = std::numeric_limits<S>::min() * S(1152921504606846976.0) * length_ * length_;  // 2^60 × least normal
    underflow_ = Dy_inexact;
    for (const auto& l : L) underflow_ = underflow_ || (l != 0 && l * l < tiny);
    if (L[0] * L[0] + L[1] * L[1] < tiny) {
      // the wobble about z is below |L| · 1e-145 (double): its squares would lose their digits to
      // underflow, and the steady rotation about ω is exact to that size
      set_steady(I, G);
      return;
    }
    const S dzx = Iz - Ix, dzy = Iz - Iy, dyx = Iy - Ix;
    S Dx = 0, Dz = 0;  // L² − 2E I_x, 2E I_z − L²: sums of same-sign terms, no cancellation
    for (std::size_t i = 0; i < 3; ++i) {
      Dx += L[i] * L[i] * ((Iw_[i] - Ix) / Iw_[i]);
      Dz += L[i] * L[i] * ((Iz - Iw_[i]) / Iw_[i]);
    }
    mc_ = std::max(S(0), dzx * Dy / (dzy * Dx));
    m_ = std::min(S(1), dyx * Dz / (dzy * Dx));
    kc_ = sqrt(mc_);
    const S sz = L[2] < 0 ? S(-1) : S(1);
    Lxm_ = sqrt(Ix * Dz / dzx);
    Lym_ = sqrt(Iy * Dz / dzy);
    Lzm_ = sz * sqrt(Iz * Dx / dzx);
    wp_ = sz * (dzy < 0 ? S(-1) : S(1)) * sqrt(Dx * dzy / (Ix * Iy * Iz));
    n_ = -Iz * dyx / (Ix * dzy);  // = −L_zm² m / L_xm², Abramowitz–Stegun sign, ≤ 0
    psi_scale_ = length_ * dzx / (Ix * Iz * wp_);
    small_n_ = n_ >= -1;
    using std::sqrt;
    amplification_ = sqrt(1 - n_);  // L_ym/L_xm ~ √|n|: how fast the direction of L⊥ turns per unit of u
    rate_ = small_n_ ? length_ / Ix : length_ / Iz;
    // initial phase from sn₀ ∝ L_y L_xm, cn₀ ∝ L_x L_ym (a common positive factor drops out)
    S s = L[1] * Lxm_, c = L[0] * Lym_;
    const S big = std::max(abs(s), abs(c));
    if (!(big > 0) || !(wp_ != 0) || !isfinite(psi_scale_)) {
      // the wobble about z is below the underflow threshold (relative size < 1e-150 in double):
      // the steady rotation about ω is exact to that size
      set_steady(I, G);
      return;
    }
    s /= big, c /= big;
    const S r = sqrt(s * s + c * c);
    s /= r, c /= r;
    separatrix_ = mc_ == 0;
    if (separatrix_) {
      if (c < 0) flip_ = S(-1), s = -s, c = -c;  // the other branch: rotation by π about z
      using std::asinh;
      u0_ = asinh(s / c);
      a_ = sqrt(-n_);
    } else {
      K_ = elliptic::complete_first_kind(mc_);
      if (n_ != 0) D_complete_ = n_ / 3 * boost::math::ellint_rj(S(0), mc_, S(1), 1 - n_, elliptic::policy());
      const S sign_s = s < 0 ? S(-1) : S(1);
      const S d2 = c * c + mc_ * s * s;
      if (abs(c) >= abs(s))  // |φ₀| ≤ π/4 or ≥ 3π/4: F directly
        u0_ = c >= 0 ? s * boost::math::ellint_rf(c * c, d2, S(1), elliptic::policy())
                     : sign_s * 2 * K_ - s * boost::math::ellint_rf(c * c, d2, S(1), elliptic::policy());
      else  // near ±K: u₀ = ±(K ∓ v), v = |c| R_F(m_c s², m_c, d²) (complementary argument)
        u0_ = sign_s * (K_ - c * boost::math::ellint_rf(mc_ * s * s, mc_, d2, elliptic::policy()));
    }
    D0_ = phase(u0_).second;
    B_ = transpose(frame(L)) * (W_ * transpose(Q0));  // R1(L(0))ᵀ A(0) in the working frame
    Wt_ = transpose(W_);
  }

  bool steady() const { return steady_; }
  /// False when a nonzero component of G is so small against |G| that its square underflows in S
  /// (below ~1e-145 |G| in double) and the motion is not the steady rotation about the stable
  /// axis: the energy differences lose that component, so a wider scalar must be used.
  bool representable() const { return steady_ || !underflow_; }
  bool separatrix() const { return separatrix_; }
  S parameter() const { return steady_ ? S(0) : m_; }
  S complementary_parameter() const { return steady_ ? S(1) : mc_; }
  S n() const { return n_; }
  /// Factor by which round-off in the phases reaches the attitude: the ellipse of L⊥ has axis ratio
  /// L_ym/L_xm = √(I_y (I_z − I_x)/(I_x (I_z − I_y))) ≈ √(1 − n), and its direction turns that much faster.
  S amplification() const { return steady_ ? S(1) : amplification_; }
  S period_phase_rate() const { return steady_ ? S(0) : wp_; }
  S quarter_period() const { return K_; }

  struct evaluation {
    body_state<S> state;
    S phase;  ///< |u| + |ψ parts|: the size of the angles whose round-off reaches the result
  };

  /// The state at time t (any sign).
  evaluation at(const S& t) const {
    using std::abs;
    using std::cos;
    using std::sin;
    if (steady_) {
      body_state<S> s{Q0_, G0_};
      if (steady_rate_ > 0) s.Q = Q0_ * rotation(steady_axis_, steady_rate_ * t);
      return {s, abs(steady_rate_ * t)};
    }
    const auto [j, D] = phase(wp_ * t + u0_);
    const vec3<S> L{flip_ * Lxm_ * j.cn, flip_ * Lym_ * j.sn, Lzm_ * j.dn};
    const S linear = rate_ * t, elliptic_part = psi_scale_ * (D - D0_), psi = linear + elliptic_part;
    // A = R1(L) Z(ψ) R1(L(0))ᵀ A(0), Z(ψ) = [[cos ψ, sin ψ, 0], [−sin ψ, cos ψ, 0], [0, 0, 1]] applied to columns
    mat3<S> FZ = frame(L);
    const S cp = cos(psi), sp = sin(psi);
    for (int i = 0; i < 3; ++i) {
      const S f0 = FZ(i, 0), f1 = FZ(i, 1);
      FZ(i, 0) = f0 * cp - f1 * sp;
      FZ(i, 1) = f0 * sp + f1 * cp;
    }
    const mat3<S> A = FZ * B_;
    // the elliptic part is a difference of D(u) and D(u₀): each is rounded at its own size
    return {{transpose(Wt_ * A), Wt_ * L}, abs(wp_ * t) + abs(u0_) + abs(linear) + abs(psi_scale_) * (abs(D) + abs(D0_))};
  }

 private:
  static std::size_t idx(int i) { return static_cast<std::size_t>(i); }

  static S det(const mat3<S>& m) {
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  }

  void set_steady(const vec3<S>& I, const vec3<S>& G) {
    using std::sqrt;
    steady_ = true;
    const vec3<S> w = angular_velocity(I, G);
    steady_rate_ = sqrt(dot(w, w));
    if (steady_rate_ > 0) steady_axis_ = {w[0] / steady_rate_, w[1] / steady_rate_, w[2] / steady_rate_};
  }

  // R1(L) of REFERENCE.md §2.3: columns (L_x L_z/(L L⊥), L_y L_z/(L L⊥), −L⊥/L), (−L_y/L⊥, L_x/L⊥, 0), L/|L|.
  mat3<S> frame(const vec3<S>& L) const {
    using std::sqrt;
    const S perp = sqrt(L[0] * L[0] + L[1] * L[1]), l = length_;
    mat3<S> r;
    r(0, 0) = L[0] * L[2] / (l * perp), r(1, 0) = L[1] * L[2] / (l * perp), r(2, 0) = -perp / l;
    r(0, 1) = -L[1] / perp, r(1, 1) = L[0] / perp, r(2, 1) = 0;
    r(0, 2) = L[0] / l, r(1, 2) = L[1] / l, r(2, 2) = L[2] / l;
    return r;
  }

  // sn, cn, dn at u and the elliptic part of ψ: D(u) = Π(am u; n|m) − u when |n| ≤ 1, Π(am u; n|m)
  // otherwise, both continued across multiples of K (D(u + 2K) = D(u) + 2 D(K)).
  std::pair<elliptic::jacobi_triple<S>, S> phase(const S& u) const {
    using std::abs;
    using std::atan;
    using std::cosh;
    using std::fmod;
    using std::round;
    using std::tanh;
    if (separatrix_) {
      // ∫₀^u du'/(1 + a² tanh² u') = (u + a atan(a tanh u))/(1 + a²), a² = −n
      const S th = tanh(u), sech = 1 / cosh(u);
      const S pi_part = (u + a_ * atan(a_ * th)) / (1 + a_ * a_);
      return {{th, sech, sech}, small_n_ ? pi_part - u : pi_part};
    }
    const S j = round(u / (2 * K_));
    const S v = u - 2 * j * K_, av = abs(v);
    const S sign_v = v < 0 ? S(-1) : S(1);
    elliptic::jacobi_triple<S> t;
    S D;  // Π − F at |v|
    if (2 * av <= K_ || mc_ >= S(0.5)) {
      t = elliptic::jacobi_functions(av, m_, mc_);
      D = elliptic::third_minus_first(t, n_, 1 - n_ * t.sn * t.sn);
    } else {
      const S w = K_ - av;
      const auto c = elliptic::jacobi_functions(w, m_, mc_);
      t = {c.cn / c.dn, kc_ * c.sn / c.dn, kc_ / c.dn};
      D = D_complete_;
      if (n_ != 0) {  // Π(am(K − w); n) = Π(n) − [m w + (−n m_c/(1 − n)) Π(am w; N)]/(m − n), A&S 17.7.16
        const S mn = m_ - n_, N = mn / (1 - n_);
        const S pi_N = w + elliptic::third_minus_first(c, N, c.cn * c.cn + mc_ / (1 - n_) * c.sn * c.sn);
        D += -n_ * w / mn + n_ * mc_ / (mn * (1 - n_)) * pi_N;
      }
    }
    t.sn *= sign_v;
    D = sign_v * D + 2 * j * D_complete_;
    if (fmod(j, S(2)) != 0) t.sn = -t.sn, t.cn = -t.cn;  // sn, cn(v + 2jK) = (−1)^j sn, cn(v)
    if (!small_n_) D += u;
    return {t, D};
  }

  mat3<S> Q0_{}, W_{}, Wt_{}, B_{};
  vec3<S> G0_{}, Iw_{}, steady_axis_{};
  S steady_rate_ = 0, length_ = 0;
  S m_ = 0, mc_ = 1, kc_ = 1, Lxm_ = 0, Lym_ = 0, Lzm_ = 0, wp_ = 0, n_ = 0, psi_scale_ = 0, rate_ = 0;
  S K_ = 0, D_complete_ = 0, u0_ = 0, D0_ = 0, a_ = 0, flip_ = 1, amplification_ = 1;
  bool steady_ = false, separatrix_ = false, small_n_ = true, underflow_ = false;
};

}  // namespace rotlie::models::detail
