#pragma once
// The full two-body problem in the centre-of-mass frame: the relative position r = x₂ − x₁ and
// velocity v, each body's attitude Q (body → inertial) and angular momentum G = Iω in its body frame
// (principal axes). H = μv²/2 + Σ Gᵢ·ωᵢ/2 + U(r, Q₁, Q₂) with μ = M₁M₂/(M₁ + M₂), so μ r̈ = F,
// Ġ = G × ω + Qᵀ M, Q̇ = Q ω̂ (mutual_gravity.hpp's F and M). The total angular momentum
// r × μv + Q₁G₁ + Q₂G₂ is conserved (r × F + M₁ + M₂ = 0). Further force terms (binary_term.hpp)
// join U, F and M through forces(x, t); without them forces(x, t) is the mutual gravity, bit for bit.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/models/scenes/binary_term.hpp"
#include "rotlie/models/scenes/mutual_gravity.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

template <class T>
struct binary_state {
  vec3<T> r{}, v{};       ///< x₂ − x₁ and its rate
  body_state<T> body[2];  ///< the primary's and the secondary's attitude and body-frame angular momentum
};

/// The pair: two bodies, each in its principal frame, G and the expansion's order.
template <class T>
class binary_system {
 public:
  binary_system(const gravitating_body<T>& primary, const gravitating_body<T>& secondary, const T& G, int order)
      : bodies_{primary, secondary}, G_(G), order_(order) {
    using std::abs;
    check_gravity_order(order);
    if (!(G > 0) || !std::isfinite(static_cast<double>(G))) throw std::invalid_argument("G must be finite and positive");
    for (int i = 0; i < 2; ++i) {
      const auto& b = bodies_[i];
      const std::string name = i == 0 ? "primary" : "secondary";
      if (!(b.mass > 0) || !std::isfinite(static_cast<double>(b.mass))) throw std::invalid_argument("the " + name + "'s mass must be finite and positive");
      check_body_integrals(b, order, name);
      for (int k = 0; k < 3; ++k) moments_[i][static_cast<std::size_t>(k)] = b.inertia(k, k);
      validate_moments(moments_[i]);
      const T scale = moments_[i][0] + moments_[i][1] + moments_[i][2];
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          if (j != k && abs(b.inertia(j, k)) > 1e-12 * scale)
            throw std::invalid_argument("the " + name + "'s body frame is not its principal frame (the inertia tensor is not diagonal)");
    }
    mu_ = primary.mass * secondary.mass / (primary.mass + secondary.mass);
  }

  const gravitating_body<T>& body(int i) const { return bodies_[i]; }
  const vec3<T>& moments(int i) const { return moments_[i]; }
  const T& G() const { return G_; }
  int order() const { return order_; }
  const T& reduced_mass() const { return mu_; }
  T total_mass() const { return bodies_[0].mass + bodies_[1].mass; }

  /// The mutual gravity alone.
  mutual_gravity<T> gravity(const binary_state<T>& x, bool point_masses = true) const {
    return mutual_gravity_at(bodies_[0], x.body[0].Q, bodies_[1], x.body[1].Q, x.r, G_, order_, point_masses);
  }

  /// Adds a force term (shared: copies of the system step with the same terms).
  void add_term(std::shared_ptr<const binary_term<T>> term) { terms_.push_back(std::move(term)); }
  const std::vector<std::shared_ptr<const binary_term<T>>>& terms() const { return terms_; }
  bool time_dependent() const {
    for (const auto& term : terms_)
      if (term->time_dependent()) return true;
    return false;
  }
  bool conserves_energy() const {
    for (const auto& term : terms_)
      if (!term->conserves_energy()) return false;
    return true;
  }

  /// The mutual gravity and every added term at time t (point_masses false: without −G M₁M₂/r's share).
  mutual_gravity<T> forces(const binary_state<T>& x, const T& t, bool point_masses = true) const {
    auto f = gravity(x, point_masses);
    for (const auto& term : terms_) term->add(x, t, f);
    return f;
  }

  T kinetic_energy(const binary_state<T>& x) const {
    return mu_ * dot(x.v, x.v) / 2 + models::kinetic_energy(moments_[0], x.body[0].G) + models::kinetic_energy(moments_[1], x.body[1].G);
  }

  T energy(const binary_state<T>& x, const T& t = T(0)) const { return kinetic_energy(x) + forces(x, t).U; }

  /// r × μv + Q₁G₁ + Q₂G₂
  vec3<T> angular_momentum(const binary_state<T>& x) const {
    const vec3<T> orbit{mu_ * (x.r[1] * x.v[2] - x.r[2] * x.v[1]), mu_ * (x.r[2] * x.v[0] - x.r[0] * x.v[2]), mu_ * (x.r[0] * x.v[1] - x.r[1] * x.v[0])};
    const vec3<T> s1 = x.body[0].Q * x.body[0].G, s2 = x.body[1].Q * x.body[1].G;
    return {orbit[0] + s1[0] + s2[0], orbit[1] + s1[1] + s2[1], orbit[2] + s1[2] + s2[2]};
  }

  /// The time derivative of the state (for the Runge–Kutta anchors): ṙ = v, v̇ = F/μ, Q̇ = Qω̂, Ġ = G × ω + QᵀM.
  binary_state<T> derivative(const binary_state<T>& x, const T& t = T(0)) const {
    const auto g = forces(x, t);
    binary_state<T> d;
    d.r = x.v;
    for (std::size_t k = 0; k < 3; ++k) d.v[k] = g.F[k] / mu_;
    for (int i = 0; i < 2; ++i) {
      euler_rhs(moments_[i], x.body[i], d.body[i]);
      const vec3<T> torque = transpose(x.body[i].Q) * (i == 0 ? g.M1 : g.M2);
      for (std::size_t k = 0; k < 3; ++k) d.body[i].G[k] += torque[k];
    }
    return d;
  }

 private:
  gravitating_body<T> bodies_[2];
  vec3<T> moments_[2];
  T G_;
  int order_;
  T mu_;
  std::vector<std::shared_ptr<const binary_term<T>>> terms_;
};

/// x + c·d, componentwise (the Runge–Kutta stages).
template <class T>
binary_state<T> displaced(const binary_state<T>& x, const binary_state<T>& d, const T& c) {
  binary_state<T> y = x;
  for (std::size_t k = 0; k < 3; ++k) y.r[k] += c * d.r[k], y.v[k] += c * d.v[k];
  for (int i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 9; ++k) y.body[i].Q.a[k] += c * d.body[i].Q.a[k];
    for (std::size_t k = 0; k < 3; ++k) y.body[i].G[k] += c * d.body[i].G[k];
  }
  return y;
}

}  // namespace rotlie::models
