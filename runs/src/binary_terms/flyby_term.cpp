// A planetary flyby (issue 45): a point mass m on a hyperbolic trajectory about the binary's
// barycentre, given by its closest approach q (km), its speed at infinity v∞ (km/s), the orbit's
// orientation i, Ω, ω (degrees; perifocal → inertial R₃(Ω) R₁(i) R₃(ω), the periapsis along the
// perifocal x̂, in the inertial frame of r) and the time of closest approach t_q (s). It moves on the
// unperturbed Kepler hyperbola about G(M + m), M the binary's mass: P(t) is the periapsis state
// (q P̂, √(v∞² + 2G(M + m)/q) Q̂) carried by the exact Kepler flow (kepler_drift.hpp) over t − t_q.
//
// Each body k, at x₁ = −(m₂/M) r and x₂ = (m₁/M) r from the barycentre, sees the perturber at
// d_k = P − x_k and feels its field to second order in the body's size (MacCullagh):
//   V_k = −G m m_k/|d| − G m tr J_k/(2|d|³) + 3 G m dᵀJ_k d/(2|d|⁵),  J_k = Q_k I_k Q_kᵀ,
// whose force on the body is ∇_d V_k and whose torque is M_k = 3 G m/|d|⁵ d × (J_k d). The relative
// orbit takes the whole difference, not its tidal expansion: F = (m₁/M) ∇V₂ − (m₂/M) ∇V₁, which for
// point masses is μ G m (d₂/|d₂|³ − d₁/|d₁|³). The potential is V₁ + V₂ + G m M/|P| (a function of
// time alone taken off, so that what is left is the tide, of order μ|r|²/|P|³); F = −∂U/∂r and M_k
// is −∂U/∂θ_k. For spheres (J_k ∝ 1) the figure's terms vanish and the bodies are point masses.
// The model leaves out the binary's pull on the perturber's path beyond that of its total mass (a
// relative (μ/M)(|r|/|P|)², the binary's own quadrupole).
#include <array>
#include <cmath>
#include <memory>

#include "rotlie/models/scenes/kepler_drift.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "term_geometry.hpp"

namespace rotlie::runs {

namespace {

using models::vec3;
using term_geometry::inertial_inertia;

class planetary_flyby final : public registered_term {
 public:
  planetary_flyby(const std::vector<double>& p, const models::binary_system<double>& sys)
      : Gm_(sys.G() * p[0]),
        GM_(sys.G() * (sys.total_mass() + p[0])),
        tq_(p[6]),
        share_{sys.body(1).mass / sys.total_mass(), sys.body(0).mass / sys.total_mass()},
        mass_{sys.body(0).mass, sys.body(1).mass},
        moments_{sys.moments(0), sys.moments(1)} {
    const double q = p[1], v_inf = p[2];
    const auto [P, Q] = term_geometry::perifocal_axes_of(p[3], p[4], p[5]);
    const double v_q = std::sqrt(v_inf * v_inf + 2 * GM_ / q);
    for (std::size_t c = 0; c < 3; ++c) r_q_[c] = q * P[c], v_q_[c] = v_q * Q[c];
  }

  bool time_dependent() const override { return true; }

  /// The perturber's position and velocity at t (km, km/s), from the barycentre.
  std::array<vec3<double>, 2> perturber(double t) const {
    vec3<double> r = r_q_, v = v_q_;
    if (t != tq_) models::kepler_drift(r, v, GM_, t - tq_);
    return {r, v};
  }

  void add(const models::binary_state<double>& x, const double& t, models::mutual_gravity<double>& f) const override {
    const auto P = perturber(t)[0];
    // the bodies' positions from the barycentre and the perturber seen from each: d₁ − d₂ = r
    vec3<double> d[2];
    for (std::size_t c = 0; c < 3; ++c) d[0][c] = P[c] + share_[0] * x.r[c], d[1][c] = P[c] - share_[1] * x.r[c];
    const double n1 = models::norm(d[0]), n2 = models::norm(d[1]), nP = models::norm(P), s1 = 1 / n1, s2 = 1 / n2;
    // point masses: μ G m (d₂/|d₂|³ − d₁/|d₁|³) = μ G m (−r/|d₂|³ + d₁ (1/|d₂|³ − 1/|d₁|³)), the last bracket
    // (|d₁| − |d₂|) s₁s₂ (s₂² + s₁s₂ + s₁²) with |d₁| − |d₂| = r·(d₁ + d₂)/(|d₁| + |d₂|): no difference of
    // nearly equal numbers
    vec3<double> sum{d[0][0] + d[1][0], d[0][1] + d[1][1], d[0][2] + d[1][2]};
    const double apart = models::dot(x.r, sum) / (n1 + n2);
    const double cubes = apart * s1 * s2 * (s2 * s2 + s1 * s2 + s1 * s1);
    const double mu = mass_[0] * share_[0];
    for (std::size_t c = 0; c < 3; ++c) f.F[c] += mu * Gm_ * (-x.r[c] * s2 * s2 * s2 + d[0][c] * cubes);
    // −G m Σ m_k (1/|d_k| − 1/|P|), with |P| − |d_k| = x_k·(P + d_k)/(|P| + |d_k|)
    for (int k = 0; k < 2; ++k) {
      const double sign = k == 0 ? -1 : 1, n = k == 0 ? n1 : n2;
      const vec3<double> xk{sign * share_[k] * x.r[0], sign * share_[k] * x.r[1], sign * share_[k] * x.r[2]};
      const vec3<double> Pd{P[0] + d[k][0], P[1] + d[k][1], P[2] + d[k][2]};
      f.U += -Gm_ * mass_[k] * models::dot(xk, Pd) / ((nP + n) * n * nP);
    }
    // each body's figure: V = G m (−tr J/(2|d|³) + 3 dᵀJd/(2|d|⁵)), ∇V = G m ((3/2) tr J d/|d|⁵ + 3 Jd/|d|⁵
    // − (15/2) dᵀJd d/|d|⁷), the torque 3 G m/|d|⁵ d × Jd; ∂d₁/∂r = m₂/M, ∂d₂/∂r = −m₁/M
    for (int k = 0; k < 2; ++k) {
      const auto& dk = d[k];
      const double s = k == 0 ? s1 : s2, s3 = s * s * s, s5 = s3 * s * s;
      const auto J = inertial_inertia(x.body[k].Q, moments_[k]);
      const auto Jd = J * dk;
      const double trace = moments_[k][0] + moments_[k][1] + moments_[k][2], dJd = models::dot(dk, Jd);
      f.U += Gm_ * (-trace * s3 / 2 + 3 * dJd * s5 / 2);
      const double along = Gm_ * (1.5 * trace * s5 - 7.5 * dJd * s5 * s * s);
      const double weight = k == 0 ? -share_[0] : share_[1];
      for (std::size_t c = 0; c < 3; ++c) f.F[c] += weight * (along * dk[c] + 3 * Gm_ * s5 * Jd[c]);
      const auto torque = models::cross(dk, Jd);
      auto& M = k == 0 ? f.M1 : f.M2;
      for (std::size_t c = 0; c < 3; ++c) M[c] += 3 * Gm_ * s5 * torque[c];
    }
  }

  nlohmann::json values(const models::binary_state<double>& x, double t) const override {
    models::mutual_gravity<double> f;
    add(x, t, f);
    const double mu = mass_[0] * share_[0];
    const vec3<double> a{f.F[0] / mu, f.F[1] / mu, f.F[2] / mu};
    const auto [P, V] = perturber(t);
    return {{"position", P}, {"velocity", V}, {"acceleration", a}, {"M1", f.M1}, {"M2", f.M2}};
  }

 private:
  double Gm_, GM_, tq_;
  double share_[2];  // m₂/M, m₁/M: x₁ = −share₀ r, x₂ = share₁ r
  double mass_[2];
  vec3<double> moments_[2], r_q_{}, v_q_{};
};

std::shared_ptr<const registered_term> make_flyby(const std::vector<double>& p, const models::binary_system<double>& sys) {
  using schemes::message_number;
  if (p.size() != 7)
    throw bad_input("--flyby takes seven values m,q,v_inf,i,Omega,omega,t_q (kg, km, km/s, three angles in degrees, s), got " + std::to_string(p.size()));
  if (!(p[0] >= 0 && p[0] <= 1e32)) throw bad_input("--flyby: the perturber's mass must be in [0, 1e32] kg (the Earth's is 5.9722e24), got " + message_number(p[0]));
  if (!(p[1] > 0 && p[1] <= 1e12)) throw bad_input("--flyby: the closest approach q must be positive, at most 1e12 km, got " + message_number(p[1]));
  if (!(p[2] > 0 && p[2] <= 3e5)) throw bad_input("--flyby: the speed at infinity v_inf must be positive, at most 3e5 km/s, got " + message_number(p[2]));
  for (std::size_t k = 3; k < 6; ++k)
    if (!(std::abs(p[k]) <= 1e6)) throw bad_input("--flyby: the angles are in degrees, within ±1e6, got " + message_number(p[k]));
  if (!(std::abs(p[6]) <= 1e15)) throw bad_input("--flyby: the time of closest approach t_q must be within ±1e15 s, got " + message_number(p[6]));
  return std::make_shared<planetary_flyby>(p, sys);
}

}  // namespace

binary_term_description flyby_term() {
  return {"flyby",
          "A planetary flyby: a point mass m (kg, or a planet by name: earth 5.9722e24, moon, mars, venus, jupiter) on the Kepler hyperbola about the barycentre of closest "
          "approach q (km) at t_q (s), speed at infinity v_inf (km/s), orientation i, Omega, omega (deg, omega the periapsis); "
          "its whole pull on each body and the quadrupole torque",
          // masses: NASA's planetary fact sheets (GM / G)
          {{"m", "kg", {{"earth", 5.9722e24}, {"moon", 7.346e22}, {"mars", 6.4171e23}, {"venus", 4.8673e24}, {"jupiter", 1.89813e27}}}, {"q", "km"}, {"v_inf", "km/s"}, {"i", "deg"}, {"Omega", "deg"}, {"omega", "deg"}, {"t_q", "s"}},
          // the Earth at Apophis's 2029 encounter (JPL: 38,000 km from the Earth's centre, v∞ 5.84 km/s), closest a day in,
          // in an orientation chosen for illustration
          "5.9722e24,38000,5.84,45,30,60,86400",
          &make_flyby};
}

}  // namespace rotlie::runs
