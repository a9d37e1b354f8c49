#pragma once
// The exact free rotation as a step: advance(state, t) takes a body from its state now to its state
// a time t later, keeping the body's constants between calls (one call per body per free flight).
// The free flight of SIER2/SIER4 (van Zon & Schofield eq. 5b) and the reference of the free-water scene.
//
// A step does not need what exact_free_body builds for a whole trajectory. The state itself gives
// sn, cn, dn at the initial phase u₀ (they are L_y/L_ym, L_x/L_xm, L_z/L_zm), so u₀ is never formed
// (no R_F), nor K, nor the complete integral of the third kind, nor the functions at u₀: the functions
// at u₀ + v (v = ω_p t) come from those at v by the addition theorem, and the elliptic part of ψ from
// D(v) plus the addition term of the third kind (complementary_elliptic.hpp). What remains per step:
// D_y, one sn cn dn and one R_J at v, an atan, sin and cos of ψ, two frames and a 3×3 product.
// The regimes this step does not take (spherical and steady bodies, the separatrix m_c = 0, a wobble or
// an energy difference at the underflow threshold, |v| > π/4, an estimate above the accuracy, bad
// input, times near the 2^60 rad limit) go to exact_free_body unchanged, with its float128 redo.
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <string_view>
#include <limits>
#include <type_traits>
#include <utility>

#include "rotlie/models/complementary_elliptic.hpp"
#include "rotlie/models/exact_energy_difference.hpp"
#include "rotlie/models/exact_free_body.hpp"

namespace rotlie::models {

namespace detail {

/// ilogb of a positive finite x (in double read from its bits: −1023 for a subnormal, which every
/// caller refuses as it refuses ilogb's smaller value).
template <class S>
int binary_exponent(const S& x) {
  if constexpr (std::is_same_v<S, double>) {
    return static_cast<int>(std::bit_cast<std::uint64_t>(x) >> 52) - 1023;
  } else {
    using std::ilogb;
    return static_cast<int>(ilogb(x));
  }
}

/// 2^e for e within the normal exponents of S (in double built from its bits).
template <class S>
S power_of_two(int e) {
  if constexpr (std::is_same_v<S, double>) {
    return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
  } else {
    using std::ldexp;
    return ldexp(S(1), e);
  }
}

/// The body's constants for a step of the closed form, and the step in the common regime.
template <class S>
class free_flight_step {
 public:
  /// A working frame of free_body_motion (x, y, z = the body axes in `axis`, signed to a proper
  /// rotation) with the constants of the closed form in it.
  struct frame_constants {
    std::array<std::size_t, 3> axis{};  // body axis of the working x, y, z
    vec3<S> sign{};                     // W(r, axis[r]): the working frame is a proper rotation
    vec3<S> Iw{}, to_x{}, to_z{};       // moments; (I_i − I_x)/I_i, (I_z − I_i)/I_i
    S dzx = 0, dzy = 0, dyx = 0, n = 0, amplification = 1;
    S x_amplitude = 0, y_amplitude = 0, z_amplitude = 0, wp_sign = 1, wp_square = 0, psi_factor = 0, rate_factor = 0;
    bool small_n = true, usable = false;
  };

  /// What depends on the body alone: the moments scaled by 2^−eI to O(1), the order of the axes,
  /// and the two working frames (D_y ≥ 0: about the largest axis; D_y < 0: about the smallest).
  /// Plain data, read by the vectorised step of many bodies (exact_free_rotation_batch.hpp).
  struct body_constants {
    int eI = 0;
    vec3<S> I{};
    S Imin = 0;
    std::array<int, 3> order{};
    std::array<frame_constants, 2> frames{};
    bool spherical = false;
  };

  /// The ε-multiple of an evaluation's phase that estimates its error (exact_free_body's).
  static constexpr double estimate_factor = exact_free_body<S>::estimate_factor;

  explicit free_flight_step(const vec3<S>& I) {
    using std::ilogb;
    using std::ldexp;
    c_.eI = static_cast<int>(ilogb(std::max({I[0], I[1], I[2]})));  // I scaled to O(1) as exact_free_body does
    for (std::size_t i = 0; i < 3; ++i) c_.I[i] = ldexp(I[i], -c_.eI);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return c_.I[idx(a)] < c_.I[idx(b)]; });
    c_.order = order;
    c_.spherical = !(c_.I[idx(order[0])] < c_.I[idx(order[2])]);
    c_.Imin = c_.I[idx(order[0])];
    c_.frames[0] = make_frame(order);  // D_y ≥ 0: the momentum circulates about the largest axis
    std::swap(order[0], order[2]);
    c_.frames[1] = make_frame(order);  // D_y < 0: about the smallest
  }

  const body_constants& constants() const { return c_; }

  /// s ← the motion from s over time t and `estimate` its error, when the state is in the common
  /// regime and the estimate is within `accuracy`; otherwise false and s untouched.
  bool advance(body_state<S>& s, const S& t, const S& accuracy, S& estimate) const {
    using std::abs;
    momentum_start p;
    S v;
    if (!prepare(s, p) || !phase(p, t, v)) return false;
    const auto [at_v, at_u] = functions_at(p, v);
    const frame_constants& f = *p.f;
    const S D_v = elliptic::third_minus_first_carlson(at_v, f.n, 1 - f.n * at_v.sn * at_v.sn);  // odd in v
    const S D_sum = elliptic::third_kind_sum_term(p.at_u0, at_v, at_u, f.n, p.m);
    // ψ = (L/I_x) t + ψ_s [D(u) − D(u₀)] when |n| ≤ 1, else (L/I_z) t + ψ_s [Π(u) − Π(u₀)] (free_body_motion)
    const S linear = p.length * f.rate_factor * scaled_time(p, t);
    const S elliptic_part = p.psi_scale * (D_v + D_sum + (f.small_n ? S(0) : v));
    const S psi = linear + elliptic_part;
    // the estimate of exact_free_body with the phases this evaluation rounds: v, the rate, and each
    // elliptic term by its own size (no u₀ here)
    const S phase = abs(v) + abs(linear) + abs(p.psi_scale) * (abs(D_v) + abs(D_sum) + (f.small_n ? S(0) : abs(v)));
    estimate = std::numeric_limits<S>::epsilon() * (2 * S(estimate_factor) + S(estimate_factor) * phase * f.amplification);
    if (!(estimate <= accuracy)) return false;
    const vec3<S> L1 = momentum_at(p, at_u);
    attitude_step(s.Q, f, momentum_frame(p.L, p.length), momentum_frame(L1, p.length), psi);
    store_momentum(p, L1, s.G);
    return true;
  }

  /// G[k] ← the body momentum of the motion from s at time t[k], the attitude not formed (one
  /// preparation for several times: the Gauss nodes of SEJ4's rotor); false, G untouched, when the
  /// state or a time is outside the common regime or a momentum's estimate exceeds `accuracy`.
  /// Each G[k] is the one advance(s, t[k]) gives, to the bit.
  template <std::size_t N>
  bool momenta(const body_state<S>& s, const std::array<S, N>& t, std::array<vec3<S>, N>& G, const S& accuracy) const {
    using std::abs;
    momentum_start p;
    if (!prepare(s, p)) return false;
    std::array<S, N> v{};
    for (std::size_t k = 0; k < N; ++k) {
      if (!phase(p, t[k], v[k])) return false;
      // only the phase v of the elliptic functions rounds here (no ψ)
      const S estimate = std::numeric_limits<S>::epsilon() * (2 * S(estimate_factor) + S(estimate_factor) * abs(v[k]));
      if (!(estimate <= accuracy)) return false;
    }
    for (std::size_t k = 0; k < N; ++k) store_momentum(p, momentum_at(p, functions_at(p, v[k]).second), G[k]);
    return true;
  }

 private:
  // scalings beyond 2^±max_scaling (where 2^e itself may not be a normal number of S): exact_free_body
  static constexpr int max_scaling = std::numeric_limits<S>::max_exponent - 8;

  // What a state fixes for every time: the working frame, the momentum there, the amplitudes, the
  // parameter and the Jacobi functions at the initial phase u₀.
  struct momentum_start {
    const frame_constants* f = nullptr;
    vec3<S> L{};
    S length = 0, Lxm = 0, Lym = 0, Lzm = 0, wp = 0, psi_scale = 0, m = 0, mc = 0, up = 0, time_scale = 0;
    elliptic::jacobi_triple<S> at_u0{};
  };

  // The state's part of a step; false in the regimes exact_free_body takes.
  bool prepare(const body_state<S>& s, momentum_start& p) const {
    using std::abs;
    using std::isfinite;
    using std::sqrt;
    if (c_.spherical) return false;
    S gmax = 0;
    for (const S& g : s.G) {
      if (!isfinite(g)) return false;
      gmax = std::max(gmax, abs(g));
    }
    for (const S& q : s.Q.a)
      if (!isfinite(q)) return false;
    if (gmax == 0) return false;
    // |G| to O(1) by a power of two (exact), as exact_free_body does; a product by 2^±e rounds as ldexp
    const int eG = binary_exponent(gmax);
    if (eG < -max_scaling || eG > max_scaling) return false;
    const S down = power_of_two<S>(-eG);
    p.up = power_of_two<S>(eG);
    const vec3<S> G{s.G[0] * down, s.G[1] * down, s.G[2] * down};
    bool Dy_inexact = false;
    const S Dy = middle_energy_difference<S>(c_.I, G, idx(c_.order[0]), idx(c_.order[1]), idx(c_.order[2]), Dy_inexact);
    const frame_constants& f = c_.frames[Dy < 0 ? 1 : 0];
    if (Dy_inexact || !f.usable) return false;
    p.f = &f;
    vec3<S>& L = p.L;
    for (std::size_t r = 0; r < 3; ++r) L[r] = f.sign[r] * G[f.axis[r]];
    const S l2 = dot(L, L);
    p.length = sqrt(l2);
    // the regimes exact_free_body sends to the steady rotation or to float128, tested as it tests them
    const vec3<S> w{L[0] / f.Iw[0], L[1] / f.Iw[1], L[2] / f.Iw[2]};
    if (L[0] * w[1] - L[1] * w[0] == 0 && L[1] * w[2] - L[2] * w[1] == 0 && L[2] * w[0] - L[0] * w[2] == 0) return false;
    const S tiny = std::numeric_limits<S>::min() * S(1152921504606846976.0) * l2;
    for (const S& l : L)
      if (l != 0 && l * l < tiny) return false;
    if (L[0] * L[0] + L[1] * L[1] < tiny) return false;
    S Dx = 0, Dz = 0;  // L² − 2E I_x, 2E I_z − L²: sums of same-sign terms
    for (std::size_t i = 0; i < 3; ++i) {
      Dx += L[i] * L[i] * f.to_x[i];
      Dz += L[i] * L[i] * f.to_z[i];
    }
    p.mc = std::max(S(0), f.dzx * Dy / (f.dzy * Dx)), p.m = std::min(S(1), f.dyx * Dz / (f.dzy * Dx));
    if (!(p.mc > 0)) return false;  // the separatrix: tanh, sech and a closed-form ψ there
    const S sz = L[2] < 0 ? S(-1) : S(1);
    p.Lxm = sqrt(Dz * f.x_amplitude), p.Lym = sqrt(Dz * f.y_amplitude), p.Lzm = sz * sqrt(Dx * f.z_amplitude);
    p.wp = sz * f.wp_sign * sqrt(Dx * f.wp_square);
    p.psi_scale = p.length * f.psi_factor / p.wp;
    S sn0 = L[1] * p.Lxm, cn0 = L[0] * p.Lym;
    const S big = std::max(abs(sn0), abs(cn0));
    if (!(big > 0) || !(p.wp != 0) || !isfinite(p.psi_scale)) return false;
    // the time in the scaled units; far below the 2^60 rad limit of exact_free_body (which refuses beyond)
    const int e_time = eG - c_.eI;
    if (e_time < -max_scaling || e_time > max_scaling) return false;
    p.time_scale = power_of_two<S>(e_time);
    sn0 /= big, cn0 /= big;
    const S norm = sqrt(sn0 * sn0 + cn0 * cn0);
    sn0 /= norm, cn0 /= norm;
    p.at_u0 = {sn0, cn0, sqrt(cn0 * cn0 + p.mc * sn0 * sn0)};
    return true;
  }

  static S scaled_time(const momentum_start& p, const S& t) { return t * p.time_scale; }

  // v = ω_p t in the scaled units; false when t is not finite, too long, or |v| > π/4.
  bool phase(const momentum_start& p, const S& t, S& v) const {
    using std::abs;
    using std::isfinite;
    if (!isfinite(t)) return false;
    const S tau = scaled_time(p, t);
    v = p.wp * tau;
    return abs(tau) * p.length <= S(576460752303423488.0) * c_.Imin && abs(v) <= boost::math::constants::half_pi<S>() / 2;
  }

  // sn cn dn at v (|v| ≤ π/4 ≤ K/2: no reduction) and, by the addition theorems, at u₀ + v
  static std::pair<elliptic::jacobi_triple<S>, elliptic::jacobi_triple<S>> functions_at(const momentum_start& p, const S& v) {
    using std::abs;
    elliptic::jacobi_triple<S> at_v =
        p.mc >= S(0.25) ? elliptic::jacobi_functions_gauss(abs(v), p.m, p.mc) : elliptic::jacobi_functions(abs(v), p.m, p.mc);
    if (v < 0) at_v.sn = -at_v.sn;
    return {at_v, elliptic::jacobi_sum(p.at_u0, at_v, p.m)};
  }

  static vec3<S> momentum_at(const momentum_start& p, const elliptic::jacobi_triple<S>& at_u) {
    return {p.Lxm * at_u.cn, p.Lym * at_u.sn, p.Lzm * at_u.dn};
  }

  static void store_momentum(const momentum_start& p, const vec3<S>& L1, vec3<S>& G) {
    for (std::size_t k = 0; k < 3; ++k) G[p.f->axis[k]] = p.f->sign[k] * L1[k] * p.up;
  }

  static std::size_t idx(int i) { return static_cast<std::size_t>(i); }

  // the working frame of free_body_motion for this order of the axes, with its constants
  frame_constants make_frame(const std::array<int, 3>& order) const {
    using std::sqrt;
    frame_constants f;
    mat3<S> W;
    for (int r = 0; r < 3; ++r) W(r, order[idx(r)]) = S(1);
    const S det = W(0, 0) * (W(1, 1) * W(2, 2) - W(1, 2) * W(2, 1)) - W(0, 1) * (W(1, 0) * W(2, 2) - W(1, 2) * W(2, 0)) +
                  W(0, 2) * (W(1, 0) * W(2, 1) - W(1, 1) * W(2, 0));
    for (std::size_t r = 0; r < 3; ++r) {
      f.axis[r] = idx(order[r]);
      f.sign[r] = r == 1 && det < 0 ? S(-1) : S(1);
      f.Iw[r] = c_.I[f.axis[r]];
    }
    const S Ix = f.Iw[0], Iy = f.Iw[1], Iz = f.Iw[2];
    f.dzx = Iz - Ix, f.dzy = Iz - Iy, f.dyx = Iy - Ix;
    for (std::size_t i = 0; i < 3; ++i) f.to_x[i] = (f.Iw[i] - Ix) / f.Iw[i], f.to_z[i] = (Iz - f.Iw[i]) / f.Iw[i];
    f.usable = !c_.spherical && f.dzy != 0;  // I_y = I_z: the circulation about z is degenerate
    if (!f.usable) return f;
    f.x_amplitude = Ix / f.dzx, f.y_amplitude = Iy / f.dzy, f.z_amplitude = Iz / f.dzx;
    f.wp_sign = f.dzy < 0 ? S(-1) : S(1);
    f.wp_square = f.dzy / (Ix * Iy * Iz);
    f.n = -Iz * f.dyx / (Ix * f.dzy);
    f.small_n = f.n >= -1;
    f.amplification = sqrt(1 - f.n);
    f.psi_factor = f.dzx / (Ix * Iz);
    f.rate_factor = f.small_n ? 1 / Ix : 1 / Iz;
    return f;
  }

  // R1(L) of REFERENCE.md §2.3 (free_body_motion's frame): columns (L_x L_z, L_y L_z, −L⊥²)/(L L⊥),
  // (−L_y, L_x, 0)/L⊥, L/L
  static mat3<S> momentum_frame(const vec3<S>& L, const S& length) {
    using std::sqrt;
    const S perp = sqrt(L[0] * L[0] + L[1] * L[1]), ip = 1 / perp, il = 1 / length, ilp = il * ip;
    mat3<S> r;
    r(0, 0) = L[0] * L[2] * ilp, r(1, 0) = L[1] * L[2] * ilp, r(2, 0) = -perp * il;
    r(0, 1) = -L[1] * ip, r(1, 1) = L[0] * ip, r(2, 1) = 0;
    r(0, 2) = L[0] * il, r(1, 2) = L[1] * il, r(2, 2) = L[2] * il;
    return r;
  }

  // Q ← Q Wᵀ R1(L₀) Z(ψ)ᵀ R1(L)ᵀ W: free_body_motion's A = R1(L) Z(ψ) R1(L₀)ᵀ A₀ with A = (Q Wᵀ)ᵀ
  static void attitude_step(mat3<S>& Q, const frame_constants& f, const mat3<S>& F0, const mat3<S>& F1, const S& psi) {
    using std::cos;
    using std::sin;
    const S cp = cos(psi), sp = sin(psi);
    mat3<S> R;  // R1(L₀) Z(ψ)ᵀ R1(L)ᵀ in the working frame
    for (int i = 0; i < 3; ++i) {
      const S a = F0(i, 0) * cp + F0(i, 1) * sp, b = F0(i, 1) * cp - F0(i, 0) * sp, c = F0(i, 2);
      for (int j = 0; j < 3; ++j) R(i, j) = a * F1(j, 0) + b * F1(j, 1) + c * F1(j, 2);
    }
    mat3<S> body;  // Wᵀ R W: W is a signed permutation
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        body(static_cast<int>(f.axis[i]), static_cast<int>(f.axis[j])) = f.sign[i] * f.sign[j] * R(static_cast<int>(i), static_cast<int>(j));
    Q = Q * body;
  }

  body_constants c_;
};

}  // namespace detail

template <class T>
class exact_free_rotation {
 public:
  static constexpr std::string_view rotor_name = "exact";  ///< in closed_form_rotors.hpp's list

  explicit exact_free_rotation(const vec3<T>& I, double accuracy = 1e-12)
      : I_(checked(I)), accuracy_(accuracy), step_(I_) {}

  const vec3<T>& moments() const { return I_; }
  double accuracy() const { return accuracy_; }
  /// The body's constants of the common regime (the vectorised step of many bodies reads them).
  const typename detail::free_flight_step<T>::body_constants& constants() const { return step_.constants(); }

  /// s ← the exact motion from s over time t; returns the evaluation's error estimate
  /// (max abs entry of Q and of G/|G|).
  T advance(body_state<T>& s, const T& t) const {
    T estimate;
    if (step_.advance(s, t, T(accuracy_), estimate)) return estimate;
    const auto r = exact_free_body<T>(I_, s, accuracy_).evaluate(t);  // every other regime, float128 redo included
    s = r.state;
    return r.error_estimate;
  }

  /// The exact body momenta of the motion from s at the times t[k] (the attitude is not formed): one
  /// preparation of the elliptic solution for all of them in the common regime, else advance per time.
  template <std::size_t N>
  std::array<vec3<T>, N> momenta(const body_state<T>& s, const std::array<T, N>& t) const {
    std::array<vec3<T>, N> G;
    if (step_.momenta(s, t, G, T(accuracy_))) return G;
    for (std::size_t k = 0; k < N; ++k) {
      body_state<T> x = s;
      advance(x, t[k]);
      G[k] = x.G;
    }
    return G;
  }

 private:
  static const vec3<T>& checked(const vec3<T>& I) {
    validate_moments(I);
    return I;
  }

  vec3<T> I_;
  double accuracy_;
  detail::free_flight_step<T> step_;
};

}  // namespace rotlie::models
