#pragma once
// SEJ4's free rotor — a RECONSTRUCTION, not Celledoni & Säfström's published method (their 2006
// paper was not seen). What is known of SEJ4 (from van Zon & Schofield): the free body momentum
// is exact (Jacobi elliptic functions), the attitude update is approximate, 4th order and time
// symmetric, and it sits inside a time-symmetric T/V splitting. Assumed here:
//   - G(t) is the exact elliptic solution (taken from exact_free_rotation);
//   - the attitude solves Q̇ = Q ω̂(s), ω = I⁻¹G(s), by the 2-point Gauss–Legendre Magnus step
//       Q(t) = Q(0) exp(θ̂),  θ = (t/2)(ω₁ + ω₂) + (√3/12) t² (ω₁ × ω₂),
//     ω_i at s_i = t (1/2 ∓ √3/6): 4th order and symmetric (the nodes mirror under t → −t).
// Inside Strang-TV the whole integrator is 2nd order; the "4" is the rotor's order.
#include <array>
#include <cmath>
#include <string_view>

#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

template <class T>
class sej4_rotor {
 public:
  static constexpr std::string_view rotor_name = "sej4";  ///< in closed_form_rotors.hpp's list

  explicit sej4_rotor(const vec3<T>& I) : exact_(I) {
    using std::sqrt;
    root3_ = sqrt(T(3));
  }

  const vec3<T>& moments() const { return exact_.moments(); }

  void advance(body_state<T>& s, const T& t) const {
    using std::sqrt;
    const T offset = root3_ / 6;
    // the exact momentum at the two Gauss nodes and at t, from one preparation of the elliptic solution
    const auto G = exact_.momenta(s, std::array<T, 3>{t * (T(1) / 2 - offset), t * (T(1) / 2 + offset), t});
    const vec3<T>& I = exact_.moments();
    const vec3<T> w1 = angular_velocity(I, G[0]), w2 = angular_velocity(I, G[1]);
    const vec3<T> c = cross(w1, w2);
    const T a = t / 2, b = root3_ / 12 * t * t;
    const vec3<T> theta{a * (w1[0] + w2[0]) + b * c[0], a * (w1[1] + w2[1]) + b * c[1], a * (w1[2] + w2[2]) + b * c[2]};
    const T angle = sqrt(dot(theta, theta));
    if (angle > 0) s.Q = s.Q * rotation(vec3<T>{theta[0] / angle, theta[1] / angle, theta[2] / angle}, angle);
    s.G = G[2];
  }

 private:
  exact_free_rotation<T> exact_;
  T root3_{};
};

}  // namespace rotlie::models
