#pragma once
// NO_SQUISH (Miller, Eleftheriou, Pattnaik, Ndirango, Newns & Martyna 2002): the free rotor split
// into rotations about the body axes, written on a unit quaternion q (body → lab) and its conjugate
// momentum π = 2 q ∘ (0, G) (REFERENCE.md §3). With P_k q = q ∘ e_k (e_1,2,3 = i, j, k), the body
// momentum is G_k = π·P_k q / 2, and the flow of G_k²/(2I_k) for time t is
//     (π, q) ← cos(φt)(π, q) + sin(φt)(P_k π, P_k q),   φ = π·P_k q / (4 I_k),
// i.e. q ← q ∘ exp(e_k φt): the body turns about its axis k by G_k t/I_k, the planar rotation of
// the matrix form (sub_flows.hpp). One free step is the symmetric sequence a (t/2), b (t/2), c (t),
// b (t/2), a (t/2) for an order of the axes (a, b, c), numbered by increasing moment as everywhere
// in rotlie. Dullweber, Leimkuhler & McLachlan's 1, 2, 3 is the table ABCBA2:ABC (MRDL;
// md_integrators.hpp), and so is LAMMPS's: it numbers the axes by decreasing moment, so its
// 3, 2, 1 with the full step on its axis 1 is rotlie's 1, 2, 3 with the full step on the largest
// moment. The reversed order 3, 2, 1 (full step on the smallest moment) is ABCBA2:CBA (MRDL-reversed).
// A torque kick is π += c h 2 q ∘ (0, τ_body), i.e. G += c h τ_body.
#include <array>
#include <cmath>
#include <stdexcept>

#include "rotlie/models/rigid_body.hpp"

namespace rotlie::models {

template <class T>
using quaternion = std::array<T, 4>;  ///< (w, x, y, z)

template <class T>
struct quaternion_state {
  quaternion<T> q{T(1), T(0), T(0), T(0)};  ///< unit, body → lab
  quaternion<T> pi{};                        ///< conjugate momentum 2 q ∘ (0, G)
};

template <class T>
quaternion<T> quaternion_product(const quaternion<T>& a, const quaternion<T>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

/// P_k x = x ∘ e_k for body axis k = 0, 1, 2.
template <class T>
quaternion<T> times_unit(const quaternion<T>& x, int k) {
  switch (k) {
    case 0: return {-x[1], x[0], x[3], -x[2]};
    case 1: return {-x[2], -x[3], x[0], x[1]};
    default: return {-x[3], x[2], -x[1], x[0]};
  }
}

/// The rotation matrix of a unit quaternion (columns: body axes in the lab frame).
template <class T>
mat3<T> rotation_of(const quaternion<T>& q) {
  const T w = q[0], x = q[1], y = q[2], z = q[3];
  mat3<T> m;
  m(0, 0) = w * w + x * x - y * y - z * z;
  m(0, 1) = 2 * (x * y - w * z);
  m(0, 2) = 2 * (x * z + w * y);
  m(1, 0) = 2 * (x * y + w * z);
  m(1, 1) = w * w - x * x + y * y - z * z;
  m(1, 2) = 2 * (y * z - w * x);
  m(2, 0) = 2 * (x * z - w * y);
  m(2, 1) = 2 * (y * z + w * x);
  m(2, 2) = w * w - x * x - y * y + z * z;
  return m;
}

/// A unit quaternion of a rotation matrix (from the largest of the four diagonal combinations, so
/// that no square root of a small difference decides the result), sign fixed by w ≥ 0.
template <class T>
quaternion<T> quaternion_of(const mat3<T>& m) {
  using std::sqrt;
  const T tr = m(0, 0) + m(1, 1) + m(2, 2);
  quaternion<T> q;
  if (tr >= m(0, 0) && tr >= m(1, 1) && tr >= m(2, 2)) {
    const T s = 2 * sqrt(1 + tr);  // 4w
    q = {s / 4, (m(2, 1) - m(1, 2)) / s, (m(0, 2) - m(2, 0)) / s, (m(1, 0) - m(0, 1)) / s};
  } else if (m(0, 0) >= m(1, 1) && m(0, 0) >= m(2, 2)) {
    const T s = 2 * sqrt(1 + m(0, 0) - m(1, 1) - m(2, 2));  // 4x
    q = {(m(2, 1) - m(1, 2)) / s, s / 4, (m(0, 1) + m(1, 0)) / s, (m(0, 2) + m(2, 0)) / s};
  } else if (m(1, 1) >= m(2, 2)) {
    const T s = 2 * sqrt(1 + m(1, 1) - m(0, 0) - m(2, 2));  // 4y
    q = {(m(0, 2) - m(2, 0)) / s, (m(0, 1) + m(1, 0)) / s, s / 4, (m(1, 2) + m(2, 1)) / s};
  } else {
    const T s = 2 * sqrt(1 + m(2, 2) - m(0, 0) - m(1, 1));  // 4z
    q = {(m(1, 0) - m(0, 1)) / s, (m(0, 2) + m(2, 0)) / s, (m(1, 2) + m(2, 1)) / s, s / 4};
  }
  if (q[0] < 0)
    for (auto& c : q) c = -c;
  return q;
}

template <class T>
quaternion_state<T> to_quaternion(const body_state<T>& s) {
  quaternion_state<T> r;
  r.q = quaternion_of(s.Q);
  const quaternion<T> g{T(0), s.G[0], s.G[1], s.G[2]};
  r.pi = quaternion_product(r.q, g);
  for (auto& c : r.pi) c *= 2;
  return r;
}

/// (Q, G) of a quaternion state: G = vec(q̄ ∘ π)/2.
template <class T>
body_state<T> from_quaternion(const quaternion_state<T>& s) {
  const quaternion<T> conj{s.q[0], -s.q[1], -s.q[2], -s.q[3]};
  const quaternion<T> g = quaternion_product(conj, s.pi);
  body_state<T> r;
  r.Q = rotation_of(s.q);
  r.G = {g[1] / 2, g[2] / 2, g[3] / 2};
  return r;
}

/// The flow of G_k²/(2 I_k) for time t.
template <class T>
void no_squish_rotate(quaternion_state<T>& s, int k, const T& moment, const T& t) {
  using std::cos;
  using std::sin;
  const quaternion<T> kq = times_unit(s.q, k), kp = times_unit(s.pi, k);
  const T phi = (s.pi[0] * kq[0] + s.pi[1] * kq[1] + s.pi[2] * kq[2] + s.pi[3] * kq[3]) / (4 * moment);
  const T c = cos(phi * t), sn = sin(phi * t);
  for (std::size_t i = 0; i < 4; ++i) {
    s.q[i] = c * s.q[i] + sn * kq[i];
    s.pi[i] = c * s.pi[i] + sn * kp[i];
  }
}

/// An order of the body axes (0-based) for the sequence a, b, c, b, a; c takes the full step.
using axis_order = std::array<int, 3>;
inline constexpr axis_order dlm_axis_order{0, 1, 2};  ///< Dullweber, Leimkuhler & McLachlan: 1, 2, 3, 2, 1
/// LAMMPS's NO_SQUISH (its axes 3, 2, 1, 2, 3 by decreasing moment): DLM's order in rotlie's numbering
inline constexpr axis_order lammps_axis_order = dlm_axis_order;
inline constexpr axis_order reversed_axis_order{2, 1, 0};  ///< 3, 2, 1, 2, 3: the full step on the smallest moment

/// The NO_SQUISH free rotor in a given axis order (LAMMPS's by default).
template <class T>
class no_squish_rotor {
 public:
  /// Throws std::invalid_argument unless `axes` is a permutation of 0, 1, 2.
  explicit no_squish_rotor(const vec3<T>& I, const axis_order& axes = lammps_axis_order) : I_(I), axes_(axes) {
    validate_moments(I_);
    bool seen[3] = {false, false, false};
    for (const int k : axes_) {
      if (k < 0 || k > 2 || seen[k]) throw std::invalid_argument("no_squish_rotor: the axis order must be a permutation of 0, 1, 2");
      seen[k] = true;
    }
  }

  void advance(quaternion_state<T>& s, const T& t) const {
    const T half = t / 2;
    const auto [a, b, c] = axes_;
    no_squish_rotate(s, a, moment(a), half);
    no_squish_rotate(s, b, moment(b), half);
    no_squish_rotate(s, c, moment(c), t);
    no_squish_rotate(s, b, moment(b), half);
    no_squish_rotate(s, a, moment(a), half);
  }

  /// A kick by the body torque for time t: π += 2 t q ∘ (0, τ_body).
  static void kick(quaternion_state<T>& s, const vec3<T>& body_torque, const T& t) {
    const quaternion<T> d = quaternion_product(s.q, quaternion<T>{T(0), body_torque[0], body_torque[1], body_torque[2]});
    for (std::size_t i = 0; i < 4; ++i) s.pi[i] += 2 * t * d[i];
  }

  const vec3<T>& moments() const { return I_; }
  const axis_order& axes() const { return axes_; }

 private:
  const T& moment(int k) const { return I_[static_cast<std::size_t>(k)]; }

  vec3<T> I_;
  axis_order axes_;
};

}  // namespace rotlie::models
