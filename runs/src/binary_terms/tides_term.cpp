// Tides of constant time lag (Mignard 1979; Hut 1981), raised on each body by the other taken as a point
// mass (issue 45). On body k, of radius R_k, Love number k₂ and time lag Δt, spinning at ω_k (inertial),
// the bulge raised by the other body of mass m pulls that body by
//   F = −3 k₂ G m² R_k⁵ / ρ¹⁰ [ρ² ρ + Δt (2 ρ (ρ·ρ̇) + ρ² (ρ × ω_k + ρ̇))],
// ρ the vector from body k to the other (r for the primary's tide, −r for the secondary's), and turns
// body k by −ρ × F, so that the total angular momentum is kept. The conservative part is the potential
// −k₂ G m² R_k⁵ / (2 ρ⁶); the lagging part dissipates energy. R_k is the radius of the homogeneous sphere
// of the body's mass and mean moment, R² = 5 (A + B + C) / (6 M) ((a² + b² + c²)/3 for an ellipsoid).
// A splitting kicks with the force at the kick's velocity and spin: exact for the conservative part,
// and of first order in the lag's coupling (k₂ Δt, tiny for an asteroid); RK4 and Odeint keep their order.
#include <cmath>
#include <memory>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

namespace {

using models::vec3;

class constant_lag_tides final : public registered_term {
 public:
  constant_lag_tides(const std::vector<double>& p, const models::binary_system<double>& sys) : G_(sys.G()) {
    for (int k = 0; k < 2; ++k) {
      const auto& I = sys.moments(k);
      radius_[k] = std::sqrt(5 * (I[0] + I[1] + I[2]) / (6 * sys.body(k).mass));
      love_[k] = p[2 * static_cast<std::size_t>(k)];
      // k₂ G m² R⁵ with m the other body's mass: the tide's strength, fixed for the run
      scale_[k] = love_[k] * G_ * sys.body(1 - k).mass * sys.body(1 - k).mass * std::pow(radius_[k], 5);
      moments_[k] = I;
      lag_[k] = p[2 * static_cast<std::size_t>(k) + 1];
    }
  }

  bool time_dependent() const override { return false; }
  bool conserves_energy() const override { return false; }

  void add(const models::binary_state<double>& x, const double& /*t*/, models::mutual_gravity<double>& f) const override {
    for (int k = 0; k < 2; ++k) {
      if (love_[k] == 0) continue;
      const double sign = k == 0 ? 1.0 : -1.0;  // ρ from body k to the other
      const vec3<double> rho{sign * x.r[0], sign * x.r[1], sign * x.r[2]}, rho_dot{sign * x.v[0], sign * x.v[1], sign * x.v[2]};
      const double d2 = models::dot(rho, rho);
      const double strength = 3 * scale_[k] / (d2 * d2 * d2 * d2 * d2);
      const auto spin = spin_of(x, k);
      const auto rho_x_spin = models::cross(rho, spin);
      const double rr = models::dot(rho, rho_dot);
      vec3<double> F{};
      for (std::size_t c = 0; c < 3; ++c) F[c] = -strength * (d2 * rho[c] + lag_[k] * (2 * rho[c] * rr + d2 * (rho_x_spin[c] + rho_dot[c])));
      // F pulls the other body: the relative coordinate's force is F for the secondary, −F for the primary
      for (std::size_t c = 0; c < 3; ++c) f.F[c] += sign * F[c];
      const auto torque = models::cross(rho, F);
      auto& M = k == 0 ? f.M1 : f.M2;
      for (std::size_t c = 0; c < 3; ++c) M[c] -= torque[c];
      f.U += -scale_[k] / (2 * d2 * d2 * d2);
    }
  }

  nlohmann::json values(const models::binary_state<double>& x, double t) const override {
    models::mutual_gravity<double> f;
    add(x, t, f);
    return {{"force", f.F}, {"M1", f.M1}, {"M2", f.M2}, {"U", f.U}, {"radii", {radius_[0], radius_[1]}}};
  }

 private:
  /// ω_k in the inertial frame: Q_k I_k⁻¹ G_k.
  vec3<double> spin_of(const models::binary_state<double>& x, int k) const { return x.body[k].Q * models::angular_velocity(moments_[k], x.body[k].G); }

  double G_;
  double radius_[2]{}, love_[2]{}, lag_[2]{}, scale_[2]{};
  vec3<double> moments_[2]{};
};

std::shared_ptr<const registered_term> make_tides(const std::vector<double>& p, const models::binary_system<double>& sys) {
  using schemes::message_number;
  if (p.size() != 4) throw bad_input("--tides takes four values k2_1,dt_1,k2_2,dt_2 (Love numbers, time lags in s), got " + std::to_string(p.size()));
  for (std::size_t k = 0; k < 4; k += 2) {
    const std::string body = k == 0 ? "the primary's" : "the secondary's";
    if (!(p[k] >= 0 && p[k] <= 1.5)) throw bad_input("--tides: " + body + " Love number k2 must be in [0, 1.5] (1.5 is a fluid body's), got " + message_number(p[k]));
    if (!(p[k + 1] >= 0 && p[k + 1] <= 1e7)) throw bad_input("--tides: " + body + " time lag must be in [0, 1e7] s, got " + message_number(p[k + 1]));
  }
  if (p[0] == 0 && p[2] == 0) throw bad_input("--tides: both Love numbers are 0 (no tide)");
  return std::make_shared<constant_lag_tides>(p, sys);
}

}  // namespace

binary_term_description tides_term() {
  return {"tides",
          "Tides of constant time lag (Mignard 1979, Hut 1981) raised on each body by the other: Love number k2 and time lag in s "
          "for each; the bulge's pull on the orbit and its torque on the body's spin",
          {{"k2_1", ""}, {"dt_1", "s"}, {"k2_2", ""}, {"dt_2", "s"}},
          "",
          &make_tides};
}

}  // namespace rotlie::runs
