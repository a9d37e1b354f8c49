// The Sun's tide on the binary (a contract of issue 43): the barycentre moves on the unperturbed
// heliocentric Kepler orbit of elements a (AU), e, i, Ω, ω, M₀ (degrees; M₀ the mean anomaly at
// t = 0) about GM☉, in the inertial frame of r, and the Sun seen from it is S(t) = −X(t). To first
// order in |r|/|S| (Hill's approximation) its pull on the relative orbit is
//   a = GM☉/|S|³ (3 Ŝ(Ŝ·r) − r),  the force μa,  the potential μΦ, Φ = −GM☉/(2|S|³) (3(Ŝ·r)² − r²),
// and to second order in each body's size its torque (MacCullagh) is
//   M_k = 3 GM☉/|S|⁵ S × (J_k S),  J_k = Q_k I_k Q_kᵀ,  the potential 3 GM☉/(2|S|⁵) Sᵀ J_k S,
// the terms of the binary's quadrupole in the Sun's field (constants in time dropped).
#include <cmath>
#include <memory>

#include "rotlie/models/scenes/kepler_orbit.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "term_geometry.hpp"

namespace rotlie::runs {

namespace {

using models::vec3;
using term_geometry::degree;
using term_geometry::inertial_inertia;

constexpr double GM_sun = 1.32712440018e11;  // km³ s⁻²
constexpr double au_km = 149597870.7;

class sun_tide final : public registered_term {
 public:
  sun_tide(const std::vector<double>& p, const models::binary_system<double>& sys)
      : a_(p[0] * au_km), orbit_(p[1]), M0_(p[5] * degree), mu_(sys.reduced_mass()), moments_{sys.moments(0), sys.moments(1)} {
    n_ = std::sqrt(GM_sun / (a_ * a_ * a_));
    const auto axes = term_geometry::perifocal_axes_of(p[2], p[3], p[4]);
    P_ = axes.P, Qv_ = axes.Q;
  }

  bool time_dependent() const override { return true; }

  /// S(t), km: the Sun seen from the barycentre.
  vec3<double> sun(double t) const {
    const double E = orbit_.eccentric_anomaly(models::kepler_orbit<double>::mean_anomaly(M0_ + n_ * t));
    const double x = a_ * (std::cos(E) - orbit_.eccentricity()), y = a_ * orbit_.root() * std::sin(E);
    return {-(x * P_[0] + y * Qv_[0]), -(x * P_[1] + y * Qv_[1]), -(x * P_[2] + y * Qv_[2])};
  }

  void add(const models::binary_state<double>& x, const double& t, models::mutual_gravity<double>& f) const override {
    const auto S = sun(t);
    const double S2 = models::dot(S, S), S1 = std::sqrt(S2), k3 = GM_sun / (S2 * S1), k5 = k3 / S2;
    const double Sr = models::dot(S, x.r);
    for (std::size_t c = 0; c < 3; ++c) f.F[c] += mu_ * k5 * (3 * Sr * S[c] - S2 * x.r[c]);
    f.U += -mu_ * k5 / 2 * (3 * Sr * Sr - S2 * models::dot(x.r, x.r));
    for (int b = 0; b < 2; ++b) {
      const auto JS = inertial_inertia(x.body[b].Q, moments_[b]) * S;
      const auto torque = models::cross(S, JS);
      auto& M = b == 0 ? f.M1 : f.M2;
      for (std::size_t c = 0; c < 3; ++c) M[c] += 3 * k5 * torque[c];
      f.U += 3 * k5 / 2 * models::dot(S, JS);
    }
  }

  nlohmann::json values(const models::binary_state<double>& x, double t) const override {
    models::mutual_gravity<double> f;
    add(x, t, f);
    const vec3<double> a{f.F[0] / mu_, f.F[1] / mu_, f.F[2] / mu_};
    return {{"position", sun(t)}, {"acceleration", a}, {"M1", f.M1}, {"M2", f.M2}};
  }

 private:
  double a_;
  models::kepler_orbit<double> orbit_;
  double M0_, n_ = 0, mu_;
  vec3<double> moments_[2], P_{}, Qv_{};
};

std::shared_ptr<const registered_term> make_sun(const std::vector<double>& p, const models::binary_system<double>& sys) {
  using schemes::message_number;
  if (p.size() != 6) throw bad_input("--sun takes six values a,e,i,Omega,omega,M0 (AU, then degrees), got " + std::to_string(p.size()));
  if (!(p[0] > 0)) throw bad_input("--sun: the semi-major axis a must be positive (AU), got " + message_number(p[0]));
  if (!(p[1] >= 0 && p[1] < 1)) throw bad_input("--sun: the eccentricity must be in [0, 1), got " + message_number(p[1]));
  for (std::size_t k = 2; k < 6; ++k)
    if (std::abs(p[k]) > 1e6) throw bad_input("--sun: the angles are in degrees, within ±1e6, got " + message_number(p[k]));
  return std::make_shared<sun_tide>(p, sys);
}

}  // namespace

binary_term_description sun_term() {
  return {"sun",
          "The Sun's tide: the barycentre on a heliocentric Kepler orbit (a in AU, angles in degrees, M0 the mean anomaly at t = 0), "
          "Hill's pull on the orbit and the quadrupole torque on each body",
          {{"a", "AU"}, {"e", ""}, {"i", "deg"}, {"Omega", "deg"}, {"omega", "deg"}, {"M0", "deg"}},
          "1.6444,0.3839,3.408,73.2,319.3,0",  // Didymos's heliocentric orbit (JPL Small-Body Database, rounded), at perihelion
          &make_sun};
}

}  // namespace rotlie::runs
